// Writing pictures in the format the file name's extension names, each through a well-kept
// library (none of these encoders is written here):
//   .png  8-bit RGBA color, 8-bit gray (stb_image_write), 16-bit gray and RGB (libpng)
//   .tga  8-bit RGBA (stb_image_write)
//   .ppm  8-bit RGB, alpha dropped (libnetpbm)
//   .exr  32-bit float channels (OpenEXR), linear: color as c / 255 (an sRGB picture's r, g, b
//         decoded, srgb.h), depth as stored
// Every file is written to a temporary name and renamed into place, so a failure never
// leaves a partial file. Errors throw std::runtime_error naming the file.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "softraster/image.h"
#include "softraster/srgb.h"

namespace softraster {

enum class PictureFormat { Png, Tga, Ppm, Exr };
// The format a path's extension names (case-insensitive), if any.
std::optional<PictureFormat> picture_format(const std::filesystem::path& path);

// A color picture, in the format of the path's extension; `color` says how its values are
// encoded (EXR stores linear light).
void write_picture(const Image& image, const std::filesystem::path& path, ColorSpace color = ColorSpace::Linear);

// 8-bit gray: PNG.
void write_gray(const GrayImage<uint8_t>& image, const std::filesystem::path& path);
// 16-bit gray: PNG.
void write_gray(const GrayImage<uint16_t>& image, const std::filesystem::path& path);
// 32-bit float, one channel named Z: EXR.
void write_gray(const GrayImage<float>& image, const std::filesystem::path& path);
// Three channels per pixel, row by row: 16-bit RGB PNG, or 32-bit float EXR (R, G, B).
void write_rgb(int width, int height, const std::vector<uint16_t>& rgb, const std::filesystem::path& path);
void write_rgb(int width, int height, const std::vector<float>& rgb, const std::filesystem::path& path);

}  // namespace softraster
