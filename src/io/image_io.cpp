#include "softraster/io/image_io.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <system_error>

#include "io/read_file.h"
#include "softraster/error.h"

namespace softraster {
namespace {

enum class Format { Png, Jpeg, Bmp, Tga, Unknown };

Format format_from_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".png") return Format::Png;
    if (ext == ".jpg" || ext == ".jpeg") return Format::Jpeg;
    if (ext == ".bmp") return Format::Bmp;
    if (ext == ".tga") return Format::Tga;
    return Format::Unknown;
}

Format format_from_contents(const std::string& b) {
    auto starts = [&](const char* magic, size_t n) { return b.size() >= n && std::memcmp(b.data(), magic, n) == 0; };
    if (starts("\x89PNG\r\n\x1a\n", 8)) return Format::Png;
    if (starts("\xff\xd8\xff", 3)) return Format::Jpeg;
    if (starts("BM", 2)) return Format::Bmp;
    return Format::Unknown;  // TGA has no signature
}

const char* format_name(Format f) {
    switch (f) {
        case Format::Png: return "PNG";
        case Format::Jpeg: return "JPEG";
        case Format::Bmp: return "BMP";
        case Format::Tga: return "TGA";
        default: return "unknown";
    }
}

uint32_t le32(const std::string& b, size_t at) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | uint8_t(b[at + size_t(i)]);
    return v;
}

// stb_image reads zeros past the end of a buffer for some formats instead of failing, so a
// truncated file would decode to a picture with a black band. These checks catch that.
void check_complete(const std::string& b, Format f, const std::string& name) {
    if (f == Format::Jpeg) {
        // A complete JPEG ends with the EOI marker (FF D9), possibly followed by padding.
        const size_t tail = b.size() > 64 ? b.size() - 64 : 0;
        if (b.rfind("\xff\xd9", std::string::npos) == std::string::npos || b.rfind("\xff\xd9") < tail)
            throw InputError(name + ": truncated JPEG (no end-of-image marker)");
    } else if (f == Format::Bmp) {
        if (b.size() < 54) throw InputError(name + ": truncated BMP header");
        const uint32_t offset = le32(b, 10), compression = le32(b, 30);
        const int32_t w = int32_t(le32(b, 18)), h = int32_t(le32(b, 22));
        const uint32_t bpp = uint8_t(b[28]) | (uint32_t(uint8_t(b[29])) << 8);
        if (compression == 0 && w > 0 && bpp > 0) {
            const uint64_t row = ((uint64_t(w) * bpp + 31) / 32) * 4;
            const uint64_t need = uint64_t(offset) + row * uint64_t(h < 0 ? -int64_t(h) : h);
            if (need > b.size()) throw InputError(name + ": truncated BMP pixel data");
        }
    } else if (f == Format::Tga) {
        if (b.size() < 18) throw InputError(name + ": truncated TGA header");
        const int type = uint8_t(b[2]);
        const uint64_t w = uint8_t(b[12]) | (uint32_t(uint8_t(b[13])) << 8);
        const uint64_t h = uint8_t(b[14]) | (uint32_t(uint8_t(b[15])) << 8);
        const uint64_t bytes = (uint64_t(uint8_t(b[16])) + 7) / 8;
        const uint64_t id_len = uint8_t(b[0]);
        const uint64_t cmap_len = (uint8_t(b[5]) | (uint32_t(uint8_t(b[6])) << 8)) * ((uint64_t(uint8_t(b[7])) + 7) / 8);
        if ((type == 1 || type == 2 || type == 3) && 18 + id_len + cmap_len + w * h * bytes > b.size())
            throw InputError(name + ": truncated TGA pixel data");
    }
}

}  // namespace

Image read_image(const std::filesystem::path& path) {
    const std::string name = path.string();
    const std::string bytes = read_whole_file(path);
    if (bytes.empty()) throw InputError(name + ": empty file");
    const Format expected = format_from_extension(path);
    if (expected == Format::Unknown)
        throw InputError(name + ": unsupported image type (expected .png, .jpg, .jpeg, .tga or .bmp)");
    const Format actual = format_from_contents(bytes);
    if (actual != expected && !(expected == Format::Tga && actual == Format::Unknown))
        throw InputError(name + ": not a " + format_name(expected) + " file" +
                         (actual != Format::Unknown ? std::string(" (contents are ") + format_name(actual) + ")" : ""));
    check_complete(bytes, expected, name);
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h,
                                          &channels, 4);
    if (!data) throw InputError(name + ": corrupt " + format_name(expected) + " (" + stbi_failure_reason() + ")");
    Image img(w, h);
    std::memcpy(img.pixels.data(), data, size_t(w) * size_t(h) * 4);
    stbi_image_free(data);
    return img;
}

std::string encode_png(const Image& image) {
    std::string out;
    auto sink = [](void* ctx, void* data, int size) { static_cast<std::string*>(ctx)->append(static_cast<char*>(data), size_t(size)); };
    if (!stbi_write_png_to_func(sink, &out, image.width, image.height, 4, image.pixels.data(), image.width * 4))
        throw std::runtime_error("PNG encoding failed");
    return out;
}

void write_png(const Image& image, const std::filesystem::path& path) {
    const std::string png = encode_png(image);
    std::filesystem::path tmp = path;
    tmp += ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(path.string() + ": cannot write (" + std::strerror(errno) + ")");
        out.write(png.data(), std::streamsize(png.size()));
        out.close();
        if (!out) {
            std::error_code ec;
            std::filesystem::remove(tmp, ec);
            throw std::runtime_error(path.string() + ": write failed");
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw std::runtime_error(path.string() + ": cannot write (" + ec.message() + ")");
    }
}

}  // namespace softraster
