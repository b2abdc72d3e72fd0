// Texture pictures in every format read_image takes: each written by OpenImageIO (or by hand
// where it has no writer), then read back as the RGBA8 texels that went in.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "softraster/error.h"
#include "softraster/io/image_io.h"
#include "softraster/io/image_write.h"

namespace softraster {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
    const fs::path dir = fs::temp_directory_path() / ("softraster_image_io_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// A 5x3 RGBA picture; `extremes` keeps every value at 0 or 255 (formats that store floats).
std::vector<uint8_t> test_pixels(int channels, bool extremes) {
    std::vector<uint8_t> p(5 * 3 * size_t(channels));
    for (size_t i = 0; i < p.size(); ++i) p[i] = extremes ? ((i * 7) % 3 == 0 ? 255 : 0) : uint8_t((i * 37 + 11) % 256);
    return p;
}

void write_with_oiio(const fs::path& path, const std::vector<uint8_t>& pixels, int channels, OIIO::TypeDesc stored) {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(5, 3, channels, stored);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the texels as given, not divided by alpha
    if (path.extension() == ".webp") spec.attribute("compression", "lossless");
    ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

void expect_texels(const Image& img, const std::vector<uint8_t>& pixels, int channels) {
    ASSERT_EQ(img.width, 5);
    ASSERT_EQ(img.height, 3);
    for (size_t i = 0; i < 15; ++i) {
        const uint8_t* p = &pixels[i * size_t(channels)];
        const Rgba8 want = channels == 1 ? Rgba8{p[0], p[0], p[0], 255}
                                         : Rgba8{p[0], p[1], p[2], channels == 4 ? p[3] : uint8_t(255)};
        EXPECT_EQ(img.pixels[i], want) << "texel " << i;
    }
}

struct Case {
    const char* extension;
    int channels;
    bool extremes;
    OIIO::TypeDesc stored;
};

TEST(ImageIo, ReadsEveryTextureFormat) {
    const fs::path dir = temp_dir();
    const Case cases[] = {
        {".png", 4, false, OIIO::TypeDesc::UINT8},  {".jpg", 3, true, OIIO::TypeDesc::UINT8},
        {".tga", 4, false, OIIO::TypeDesc::UINT8},  {".bmp", 3, false, OIIO::TypeDesc::UINT8},
        {".rgb", 3, false, OIIO::TypeDesc::UINT8},  {".sgi", 1, false, OIIO::TypeDesc::UINT8},
        {".tif", 4, false, OIIO::TypeDesc::UINT8},  {".webp", 4, false, OIIO::TypeDesc::UINT8},
        {".hdr", 3, true, OIIO::TypeDesc::FLOAT},   {".exr", 4, true, OIIO::TypeDesc::HALF},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.extension);
        const fs::path path = dir / (std::string("picture") + c.extension);
        const std::vector<uint8_t> pixels = test_pixels(c.channels, c.extremes);
        write_with_oiio(path, pixels, c.channels, c.stored);
        if (c.extension == std::string(".jpg") || c.extension == std::string(".webp")) {
            // Lossy color: the size, and WebP's alpha, which it keeps exactly.
            const Image img = read_image(path);
            EXPECT_EQ(img.width, 5);
            EXPECT_EQ(img.height, 3);
            if (c.channels == 4) {
                for (size_t i = 0; i < 15; ++i) EXPECT_EQ(img.pixels[i].a, pixels[i * 4 + 3]) << "texel " << i;
            }
            continue;
        }
        expect_texels(read_image(path), pixels, c.channels);
    }
    fs::remove_all(dir);
}

// DDS, which OpenImageIO reads but cannot write: an uncompressed 32-bit BGRA file by hand
// (Microsoft's DDS_HEADER: magic, 124-byte header with a 32-byte pixel format, then texels).
TEST(ImageIo, ReadsUncompressedDds) {
    std::string dds = "DDS ";
    auto u32 = [&](uint32_t v) { for (int i = 0; i < 4; ++i) dds += char((v >> (8 * i)) & 0xff); };
    u32(124); u32(0x1 | 0x2 | 0x4 | 0x1000); u32(3); u32(5); u32(20); u32(0); u32(1);
    for (int i = 0; i < 11; ++i) u32(0);
    u32(32); u32(0x1 | 0x40); u32(0); u32(32);                  // pixel format: alpha + RGB, 32 bits
    u32(0x00ff0000); u32(0x0000ff00); u32(0x000000ff); u32(0xff000000);
    u32(0x1000); u32(0); u32(0); u32(0); u32(0);
    const std::vector<uint8_t> rgba = test_pixels(4, false);
    for (size_t i = 0; i < 15; ++i)
        for (size_t c : {2, 1, 0, 3}) dds += char(rgba[i * 4 + c]);
    const fs::path dir = temp_dir();
    std::ofstream(dir / "picture.dds", std::ios::binary) << dds;
    expect_texels(read_image(dir / "picture.dds"), rgba, 4);
    fs::remove_all(dir);
}

TEST(ImageIo, BytesInMemoryReadAsFromAFile) {
    const fs::path dir = temp_dir();
    const fs::path path = dir / "picture.png";
    const std::vector<uint8_t> pixels = test_pixels(4, false);
    write_with_oiio(path, pixels, 4, OIIO::TypeDesc::UINT8);
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    expect_texels(read_image(bytes, "embedded", "PNG"), pixels, 4);
    EXPECT_THROW(read_image(bytes.substr(0, bytes.size() / 2), "embedded", "png"), InputError);
    EXPECT_THROW(read_image(bytes, "embedded", "xyz"), InputError);
    fs::remove_all(dir);
}


// An EXR picture holds linear light: a linear picture's values / 255, an sRGB picture's
// decoded (alpha / 255 either way).
TEST(ImageWrite, ExrHoldsLinearLight) {
    Image img(2, 1);
    img.at(0, 0) = {188, 0, 255, 128};
    img.at(1, 0) = {128, 64, 1, 255};
    for (ColorSpace space : {ColorSpace::Linear, ColorSpace::Srgb}) {
        const fs::path path = temp_dir() / (space == ColorSpace::Srgb ? "srgb.exr" : "linear.exr");
        write_picture(img, path, space);
        auto in = OIIO::ImageInput::open(path.string());
        ASSERT_TRUE(in) << OIIO::geterror();
        std::vector<float> px(8);
        ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, px.data()));
        for (int p = 0; p < 2; ++p)
            for (int c = 0; c < 4; ++c) {
                const uint8_t v = (&img.at(p, 0).r)[c];
                const float want = space == ColorSpace::Srgb && c < 3 ? srgb::decode(v) : float(v) / 255.0f;
                EXPECT_EQ(px[size_t(4 * p + c)], want) << p << " " << c;
            }
    }
}

}  // namespace
}  // namespace softraster
