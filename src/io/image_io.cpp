#include "softraster/io/image_io.h"

#include "softraster/io/atomic_write.h"

#include <png.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <system_error>
#include <vector>

#include <stb_image.h>
#include <zlib.h>

#include "io/modules.h"
#include "io/oiio_module.h"
#include "io/read_file.h"
#include "softraster/error.h"

namespace softraster {
namespace {


enum class Format { Png, Jpeg, Bmp, Tga, Other, Unknown };

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// The four formats of the scene format's version 1 get signature and completeness checks of
// their own (below); the others are left to the decoder.
Format format_from_extension(const std::string& ext) {
    if (ext == ".png") return Format::Png;
    if (ext == ".jpg" || ext == ".jpeg") return Format::Jpeg;
    if (ext == ".bmp") return Format::Bmp;
    if (ext == ".tga") return Format::Tga;
    for (const char* other : {".rgb", ".rgba", ".sgi", ".bw", ".dds", ".tif", ".tiff", ".webp", ".hdr", ".exr"})
        if (ext == other) return Format::Other;
    return Format::Unknown;
}

Format format_from_contents(std::string_view b) {
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

uint32_t le32(std::string_view b, size_t at) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | uint8_t(b[at + size_t(i)]);
    return v;
}

// Decoders fill the missing part of a truncated file with zeros or gray for some formats
// (libjpeg warns and goes on), so such a file would decode to a picture with a band of
// garbage. These checks catch that.
uint32_t be32(std::string_view b, size_t at) {
    uint32_t v = 0;
    for (size_t i = 0; i < 4; ++i) v = (v << 8) | uint8_t(b[at + i]);
    return v;
}

// A PNG is a signature and chunks (length, type, data, CRC-32 of type and data) up to IEND
// (PNG specification, section 5). Walking them finds truncation and damage before libpng
// does: libpng reports those on stderr itself, and our errors are one line.
void check_png_chunks(std::string_view b, const std::string& name) {
    size_t at = 8;
    while (true) {
        if (at + 12 > b.size()) throw InputError(name + ": truncated PNG (no IEND chunk)");
        const uint32_t length = be32(b, at);
        const std::string_view type = b.substr(at + 4, 4);
        if (length > b.size() - at - 12) throw InputError(name + ": truncated PNG (chunk " + std::string(type) + ")");
        for (char c : type)
            if (!std::isalpha(static_cast<unsigned char>(c))) throw InputError(name + ": corrupt PNG (bad chunk type)");
        const auto* typed = reinterpret_cast<const Bytef*>(b.data() + at + 4);
        if (crc32(0, typed, uInt(length + 4)) != be32(b, at + 8 + length))
            throw InputError(name + ": corrupt PNG (checksum of chunk " + std::string(type) + ")");
        if (type == "IEND") return;
        at += 12 + size_t(length);
    }
}

void check_complete(std::string_view b, Format f, const std::string& name) {
    if (f == Format::Png) {
        check_png_chunks(b, name);
    } else if (f == Format::Jpeg) {
        // A complete JPEG ends with the EOI marker (FF D9), possibly followed by padding.
        const size_t tail = b.size() > 64 ? b.size() - 64 : 0;
        if (b.rfind("\xff\xd9") == std::string_view::npos || b.rfind("\xff\xd9") < tail)
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


// The largest picture a texture may be: 2^28 texels (1 GiB of RGBA8), and 65536 a side (the
// sampler's fixed-point texel coordinates, texture.h).
constexpr uint64_t kMaxTexels = uint64_t(1) << 28;
constexpr int kMaxSide = 65536;

// The OpenImageIO module's decode function, opened on first use (oiio_module.h, modules.h).
SoftrasterDecodeFn oiio_decoder(const std::string& name) {
    return reinterpret_cast<SoftrasterDecodeFn>(
        required_module_entry(SOFTRASTER_OIIO_MODULE, SOFTRASTER_OIIO_DECODE, name + ": this picture format needs softraster's OpenImageIO module"));
}

Image decode_with_oiio(std::string_view bytes, const std::filesystem::path* file, const std::string& name, const std::string& ext) {
    SoftrasterDecoded out;
    oiio_decoder(name)(file ? file->c_str() : nullptr, bytes.data(), bytes.size(), ext.c_str(), &out);
    if (!out.rgba) throw InputError(name + ": " + out.error);
    Image img(out.width, out.height);
    std::memcpy(img.pixels.data(), out.rgba, img.pixels.size() * 4);
    std::free(out.rgba);
    return img;
}

// PNG, JPEG, TGA and BMP, the formats of nearly every asset's textures, decode with stb_image
// in the program itself; the others through the OpenImageIO module.
Image decode(std::string_view bytes, const std::filesystem::path* file, const std::string& name, const std::string& ext,
             Format format) {
    if (format == Format::Other) return decode_with_oiio(bytes, file, name, ext);
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h, &channels))
        throw InputError(name + ": corrupt " + format_name(format) + " (" + stbi_failure_reason() + ")");
    if (uint64_t(w) * uint64_t(h) > kMaxTexels || w > kMaxSide || h > kMaxSide)
        throw InputError(name + ": picture too large (" + std::to_string(w) + "x" + std::to_string(h) + ")");
    stbi_uc* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &w, &h,
                                          &channels, 4);
    if (!data) throw InputError(name + ": corrupt " + format_name(format) + " (" + stbi_failure_reason() + ")");
    Image img(w, h);
    std::memcpy(img.pixels.data(), data, size_t(w) * size_t(h) * 4);
    stbi_image_free(data);
    return img;
}

Image decode_checked(std::string_view bytes, const std::filesystem::path* file, const std::string& name, const std::string& ext) {
    if (bytes.empty()) throw InputError(name + ": empty file");
    const Format expected = format_from_extension(ext);
    if (expected == Format::Unknown)
        throw InputError(name + ": unsupported image type (expected " + std::string(kImageExtensions) + ")");
    if (expected != Format::Other) {
        const Format actual = format_from_contents(bytes);
        if (actual != expected && !(expected == Format::Tga && actual == Format::Unknown))
            throw InputError(name + ": not a " + format_name(expected) + " file" +
                             (actual != Format::Unknown ? std::string(" (contents are ") + format_name(actual) + ")" : ""));
        check_complete(bytes, expected, name);
    }
    return decode(bytes, file, name, ext, expected);
}

}  // namespace

Image read_image(const std::filesystem::path& path) {
    return decode_checked(read_whole_file(path), &path, path.string(), lower_extension(path));
}

Image read_image(std::string_view bytes, const std::string& name, const std::string& type) {
    std::string ext = "." + type;
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return decode_checked(bytes, nullptr, name, ext);
}

// Through libpng, into a buffer of the largest size the picture can take (libpng's bound):
// one pass. (libpng rather than stb_image_write: about 30% faster, and files about 30%
// smaller, docs/performance.md "The resolve and MSAA's two passes".)
std::string encode_png(const Image& image) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(image.width);
    png.height = png_uint_32(image.height);
    png.format = PNG_FORMAT_RGBA;
    png_alloc_size_t size = PNG_IMAGE_PNG_SIZE_MAX(png);
    std::string out(size, '\0');
    if (!png_image_write_to_memory(&png, out.data(), &size, 0, image.pixels.data(), 0, nullptr))
        throw std::runtime_error(std::string("PNG encoding failed: ") + png.message);
    out.resize(size);
    return out;
}

void write_png(const Image& image, const std::filesystem::path& path) {
    write_file_atomically(path, encode_png(image));
}

}  // namespace softraster
