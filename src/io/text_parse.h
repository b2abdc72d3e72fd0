// Small, strict text helpers shared by the OBJ and PLY readers.
#pragma once
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace softraster {

// Whitespace-separated tokens of a line.
std::vector<std::string_view> split_tokens(std::string_view line);

// Whole-token number parsing: false if anything but the number is in the token.
// Doubles accept "nan", "inf" and a leading '+'.
bool parse_double(std::string_view token, double& out);
bool parse_int64(std::string_view token, int64_t& out);

}  // namespace softraster
