// Writing the rendered picture, shared by the commands that produce one.
#pragma once
#include <chrono>
#include <filesystem>
#include <string>

#include "softraster/image.h"

namespace softraster::cli {

// Checks an output path before any work: it must end in .png and its folder must exist.
// Throws InputError otherwise.
void check_output_path(const std::filesystem::path& out);

// Writes the PNG (atomically) and prints one summary line to stderr.
void write_output(const Image& image, const std::filesystem::path& out, std::chrono::duration<double> elapsed);

}  // namespace softraster::cli
