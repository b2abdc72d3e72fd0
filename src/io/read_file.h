// Reading a whole file (text or binary) for the loaders.
#pragma once
#include <filesystem>
#include <string>

namespace softraster {

// The file's bytes, or InputError("<path>: file not found" / "is a directory" / "cannot open").
std::string read_whole_file(const std::filesystem::path& path);

}  // namespace softraster
