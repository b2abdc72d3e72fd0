#include "softraster/io/image_write.h"

#include "softraster/io/atomic_write.h"
#include "softraster/io/image_io.h"

#include <png.h>
#include <stb_image_write.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <netpbm/ppm.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>

namespace softraster {
namespace {


struct File {
    FILE* f;
    File(const std::string& name, const std::filesystem::path& shown) : f(std::fopen(name.c_str(), "wb")) {
        if (!f) throw std::runtime_error(shown.string() + ": cannot write (" + std::strerror(errno) + ")");
    }
    ~File() {
        if (f) std::fclose(f);
    }
    void close(const std::filesystem::path& shown) {
        const bool bad = std::ferror(f) != 0;
        const int rc = std::fclose(f);
        f = nullptr;
        if (bad || rc != 0) throw std::runtime_error(shown.string() + ": write failed");
    }
};

void write_exr(int width, int height, const std::vector<std::pair<const char*, const float*>>& channels, size_t stride,
               const std::filesystem::path& path) {
    write_atomically(path, [&](const std::string& tmp) {
        try {
            Imf::Header header(width, height);
            Imf::FrameBuffer frame;
            for (const auto& [name, base] : channels) {
                header.channels().insert(name, Imf::Channel(Imf::FLOAT));
                frame.insert(name, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(base)), sizeof(float) * stride,
                                              sizeof(float) * stride * size_t(width)));
            }
            Imf::OutputFile file(tmp.c_str(), header);
            file.setFrameBuffer(frame);
            file.writePixels(height);
        } catch (const std::exception& e) {
            throw std::runtime_error(path.string() + ": " + e.what());
        }
    });
}

// A gray or 16-bit PNG through libpng's simplified API (an RGBA picture: image_io.h's
// write_png): 8-bit formats as given, the LINEAR ones as 16-bit values.
void write_png_file(const std::filesystem::path& path, int width, int height, png_uint_32 format, const void* pixels) {
    write_atomically(path, [&](const std::string& tmp) {
        png_image png{};
        png.version = PNG_IMAGE_VERSION;
        png.width = png_uint_32(width);
        png.height = png_uint_32(height);
        png.format = format;
        if (!png_image_write_to_file(&png, tmp.c_str(), 0, pixels, 0, nullptr)) throw std::runtime_error(path.string() + ": " + png.message);
    });
}

}  // namespace

std::optional<PictureFormat> picture_format(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".png") return PictureFormat::Png;
    if (ext == ".tga") return PictureFormat::Tga;
    if (ext == ".ppm") return PictureFormat::Ppm;
    if (ext == ".exr") return PictureFormat::Exr;
    return std::nullopt;
}

void write_picture(const Image& image, const std::filesystem::path& path, ColorSpace color) {
    const auto format = picture_format(path);
    if (!format) throw std::runtime_error(path.string() + ": unknown picture format (use .png, .tga, .ppm or .exr)");
    switch (*format) {
        case PictureFormat::Png:
            write_png(image, path);
            return;
        case PictureFormat::Tga:
            write_atomically(path, [&](const std::string& tmp) {
                if (!stbi_write_tga(tmp.c_str(), image.width, image.height, 4, image.pixels.data()))
                    throw std::runtime_error(path.string() + ": write failed");
            });
            return;
        case PictureFormat::Ppm:
            write_atomically(path, [&](const std::string& tmp) {
                File file(tmp, path);
                ppm_writeppminit(file.f, image.width, image.height, 255, 0);
                std::vector<pixel> row(size_t(image.width));
                for (int y = 0; y < image.height; ++y) {
                    for (int x = 0; x < image.width; ++x) {
                        const Rgba8 c = image.at(x, y);
                        PPM_ASSIGN(row[size_t(x)], c.r, c.g, c.b);
                    }
                    ppm_writeppmrow(file.f, row.data(), image.width, 255, 0);
                }
                file.close(path);
            });
            return;
        case PictureFormat::Exr: {
            std::vector<float> rgba(image.pixels.size() * 4);
            for (size_t i = 0; i < image.pixels.size(); ++i) {
                const Rgba8 c = image.pixels[i];
                if (color == ColorSpace::Srgb) rgba[4 * i] = srgb::decode(c.r), rgba[4 * i + 1] = srgb::decode(c.g), rgba[4 * i + 2] = srgb::decode(c.b);
                else rgba[4 * i] = c.r / 255.0f, rgba[4 * i + 1] = c.g / 255.0f, rgba[4 * i + 2] = c.b / 255.0f;
                rgba[4 * i + 3] = c.a / 255.0f;
            }
            write_exr(image.width, image.height, {{"R", rgba.data()}, {"G", rgba.data() + 1}, {"B", rgba.data() + 2}, {"A", rgba.data() + 3}},
                      4, path);
            return;
        }
    }
}

void write_gray(const GrayImage<uint8_t>& image, const std::filesystem::path& path) {
    if (picture_format(path) != PictureFormat::Png) throw std::runtime_error(path.string() + ": an 8-bit gray picture is written as .png");
    write_png_file(path, image.width, image.height, PNG_FORMAT_GRAY, image.values.data());
}

void write_gray(const GrayImage<uint16_t>& image, const std::filesystem::path& path) {
    if (picture_format(path) != PictureFormat::Png) throw std::runtime_error(path.string() + ": a 16-bit gray picture is written as .png");
    write_png_file(path, image.width, image.height, PNG_FORMAT_LINEAR_Y, image.values.data());  // 16-bit gray, stored as given
}

void write_gray(const GrayImage<float>& image, const std::filesystem::path& path) {
    if (picture_format(path) != PictureFormat::Exr) throw std::runtime_error(path.string() + ": a float picture is written as .exr");
    write_exr(image.width, image.height, {{"Z", image.values.data()}}, 1, path);
}

void write_rgb(int width, int height, const std::vector<uint16_t>& rgb, const std::filesystem::path& path) {
    if (picture_format(path) != PictureFormat::Png) throw std::runtime_error(path.string() + ": a 16-bit RGB picture is written as .png");
    write_png_file(path, width, height, PNG_FORMAT_LINEAR_RGB, rgb.data());  // 16-bit RGB, stored as given
}

void write_rgb(int width, int height, const std::vector<float>& rgb, const std::filesystem::path& path) {
    if (picture_format(path) != PictureFormat::Exr) throw std::runtime_error(path.string() + ": a float RGB picture is written as .exr");
    write_exr(width, height, {{"R", rgb.data()}, {"G", rgb.data() + 1}, {"B", rgb.data() + 2}}, 3, path);
}

}  // namespace softraster
