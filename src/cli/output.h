// Writing the rendered picture, shared by the commands that produce one.
#pragma once
#include <chrono>
#include <filesystem>
#include <string>

#include "softraster/image.h"
#include "softraster/io/image_write.h"

namespace softraster::cli {

// Checks an output path before any work: its extension must name one of the `allowed`
// picture formats (image_write.h) and its folder must exist. Throws InputError otherwise.
void check_output_path(const std::filesystem::path& out,
                       std::initializer_list<PictureFormat> allowed = {PictureFormat::Png, PictureFormat::Tga, PictureFormat::Ppm,
                                                                      PictureFormat::Exr});

// Writes the picture (atomically) in its extension's format and prints one summary line to stderr.
void write_output(const Image& image, const std::filesystem::path& out, std::chrono::duration<double> elapsed,
                  ColorSpace color = ColorSpace::Linear);

}  // namespace softraster::cli
