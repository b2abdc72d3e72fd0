// Reading and writing image files: PNG, JPEG, TGA, BMP in through stb_image; SGI, DDS, TIFF,
// WebP, HDR and EXR through OpenImageIO (a module opened when first needed, src/io/oiio_module.h);
// PNG out through stb.
#pragma once
#include <filesystem>
#include <string>
#include <string_view>

#include "softraster/image.h"

namespace softraster {

// Decodes an image file to 8-bit RGBA (alpha 255 when the file has none), row 0 at the top.
// The format is taken from the file's contents and must agree with its extension.
// Throws InputError("<path>: <what is wrong>") for a missing, truncated or corrupt file.
Image read_image(const std::filesystem::path& path);
// The same for a file's bytes held in memory (a texture embedded in a model): `type` is the
// extension without the dot ("png", "jpg"), `name` labels the errors.
Image read_image(std::string_view bytes, const std::string& name, const std::string& type);

// The extensions read_image accepts, for messages.
inline constexpr const char* kImageExtensions =
    ".png, .jpg, .jpeg, .tga, .bmp, .rgb, .rgba, .sgi, .bw, .dds, .tif, .tiff, .webp, .hdr or .exr";

// Writes a PNG all at once: the picture goes to a temporary file that is renamed into place,
// so a failure never leaves a partial file. Throws std::runtime_error when it cannot write.
void write_png(const Image& image, const std::filesystem::path& path);

// The PNG file bytes of an image.
std::string encode_png(const Image& image);

}  // namespace softraster
