// libsoftraster_oiio.so: pictures decoded by OpenImageIO (see oiio_module.h for why this is
// a module of its own).
#include "io/oiio_module.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace {

// The largest picture a texture may be: 2^28 texels (1 GiB of RGBA8).
constexpr uint64_t kMaxTexels = uint64_t(1) << 28;
constexpr int kMaxSide = 65536;  // (image_io.cpp)

void set_error(SoftrasterDecoded* out, std::string what) {
    std::replace(what.begin(), what.end(), '\n', ' ');
    while (!what.empty() && what.back() == ' ') what.pop_back();
    if (what.empty()) what = "unknown reason";
    std::snprintf(out->error, sizeof out->error, "%s", what.c_str());
}

}  // namespace

// Gray is copied to red, green and blue, a missing alpha is 255, and floating-point pictures
// (HDR, EXR) are clamped to [0, 1] and scaled, without tone mapping.
extern "C" __attribute__((visibility("default"))) void softraster_oiio_decode(const char* path, const char* bytes, size_t size,
                                                                             const char* ext, SoftrasterDecoded* out) {
    *out = SoftrasterDecoded{0, 0, nullptr, {0}};
    try {
        // Texels as stored: OpenImageIO would premultiply color by alpha (PNG, TGA, TIFF...).
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        OIIO::Filesystem::IOMemReader memory(bytes, size);
        OIIO::Filesystem::IOProxy* proxy = &memory;
        if (!path) config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
        // The decoder is chosen by the extension (a memory reader's name only labels messages).
        auto in = OIIO::ImageInput::open(path ? std::string(path) : "memory" + std::string(ext), &config, path ? nullptr : proxy);
        if (!in) return set_error(out, "cannot decode (" + OIIO::geterror() + ")");
        const OIIO::ImageSpec& spec = in->spec();
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth != 1)
            return set_error(out, "unsupported picture layout (" + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                      ", " + std::to_string(spec.nchannels) + " channels)");
        if (uint64_t(spec.width) * uint64_t(spec.height) > kMaxTexels || spec.width > kMaxSide || spec.height > kMaxSide)
            return set_error(out, "picture too large (" + std::to_string(spec.width) + "x" + std::to_string(spec.height) + ")");
        const int channels = std::min(spec.nchannels, 4);
        const size_t texels = size_t(spec.width) * size_t(spec.height);
        std::vector<uint8_t> data(texels * size_t(channels));
        if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, data.data()))
            return set_error(out, "corrupt picture (" + in->geterror() + ")");
        auto* rgba = static_cast<uint8_t*>(std::malloc(texels * 4));
        if (!rgba) return set_error(out, "out of memory");
        for (size_t i = 0; i < texels; ++i) {
            const uint8_t* p = &data[i * size_t(channels)];
            uint8_t* q = &rgba[i * 4];
            q[0] = p[0];
            q[1] = channels <= 2 ? p[0] : p[1];
            q[2] = channels <= 2 ? p[0] : p[2];
            q[3] = channels == 2 ? p[1] : channels == 4 ? p[3] : uint8_t(255);
        }
        out->width = spec.width;
        out->height = spec.height;
        out->rgba = rgba;
    } catch (const std::exception& e) {
        set_error(out, std::string("cannot decode (") + e.what() + ")");
    }
}
