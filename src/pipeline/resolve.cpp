// Stage 13, resolve: the multisampled buffer becomes the picture.
// Each channel of a pixel is floor(mean + 0.5) of its stored 8-bit samples; in an sRGB
// buffer r, g, b average in linear light: the mean of the decoded samples, encoded.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "softraster/pipeline/resolve.h"
#include "softraster/worker_pool.h"

namespace softraster {
namespace {

// The sRGB mean of n stored colors: r, g, b decoded, averaged and encoded (in the order
// given, a sum then a multiplication); alpha as in a linear buffer.
template <class At>
Rgba8 srgb_mean(const srgb::Tables& t, unsigned n, At&& at) {
    float sum[3] = {0, 0, 0};
    unsigned alpha = n / 2;
    for (unsigned i = 0; i < n; ++i) {
        const Rgba8 c = at(i);
        sum[0] += t.decode[c.r], sum[1] += t.decode[c.g], sum[2] += t.decode[c.b];
        alpha += c.a;
    }
    const float inv = 1.0f / float(n);
    return {srgb::encode(t, sum[0] * inv), srgb::encode(t, sum[1] * inv), srgb::encode(t, sum[2] * inv), uint8_t(alpha / n)};
}

// Whether the N samples of a pixel are one color, as inside a triangle: their mean is that
// color in either color space (the sRGB mean of N equal values encodes back to the value,
// which Resolve.EqualSamplesKeepTheirColor checks for every value and count). Two samples
// to a 64-bit word: the first word's halves equal, and every word equal to the first.
template <unsigned N>
bool all_equal(const uint32_t* s) {
    static_assert(N % 2 == 0);
    uint64_t first;
    std::memcpy(&first, s, sizeof first);
    uint64_t differ = (first ^ (first >> 32)) & 0xffffffffu;
    for (unsigned i = 2; i < N; i += 2) {
        uint64_t word;
        std::memcpy(&word, s + i, sizeof word);
        differ |= word ^ first;
    }
    return differ == 0;
}

// Pixels [begin, end) of the picture.
void resolve_pixels(const Framebuffer& fb, Image& img, size_t begin, size_t end) {
    const auto n = unsigned(fb.samples());
    const auto* words = reinterpret_cast<const uint32_t*>(fb.color_plane());
    auto* out = reinterpret_cast<uint32_t*>(img.pixels.data());
    static_assert(sizeof(Rgba8) == 4);
    if (fb.srgb()) {
        const srgb::Tables& t = srgb::tables();
        const Rgba8* c = fb.color_plane();
        auto pixels = [&]<unsigned N>() {
            for (size_t p = begin; p < end; ++p) {
                const uint32_t* s = words + N * p;
                if (all_equal<N>(s)) out[p] = s[0];
                else img.pixels[p] = srgb_mean(t, N, [&](unsigned i) { return c[N * p + i]; });
            }
        };
        switch (n) {
            case 2: return pixels.template operator()<2>();
            case 4: return pixels.template operator()<4>();
            case 8: return pixels.template operator()<8>();
            default: return pixels.template operator()<16>();
        }
    }
    if (n != 4) {  // 2, 8, 16: the same rounding, channel by channel
        const Rgba8* c = fb.color_plane();
        for (size_t p = begin; p < end; ++p) {
            const Rgba8* s = c + n * p;
            unsigned sum[4] = {n / 2, n / 2, n / 2, n / 2};
            for (unsigned i = 0; i < n; ++i) sum[0] += s[i].r, sum[1] += s[i].g, sum[2] += s[i].b, sum[3] += s[i].a;
            img.pixels[p] = {uint8_t(sum[0] / n), uint8_t(sum[1] / n), uint8_t(sum[2] / n), uint8_t(sum[3] / n)};
        }
        return;
    }
    // 4x: average each channel of the four samples, floor(mean + 0.5) = (sum + 2) >> 2. The
    // four RGBA8 samples are four 32-bit words; channels 0 and 2, and 1 and 3, are summed two
    // at a time in 16-bit lanes (SIMD within a register).
    for (size_t p = begin; p < end; ++p) {
        const uint32_t* s = words + 4 * p;
        uint32_t even = 0x00020002u, odd = 0x00020002u;  // + 2 for rounding
        for (int i = 0; i < 4; ++i) {
            even += s[i] & 0x00ff00ffu;
            odd += (s[i] >> 8) & 0x00ff00ffu;
        }
        out[p] = ((even >> 2) & 0x00ff00ffu) | (((odd >> 2) & 0x00ff00ffu) << 8);
    }
}

}  // namespace

void resolve(const Framebuffer& fb, Image& img, WorkerPool* pool) {
    if (img.width != fb.width() || img.height != fb.height()) img = Image(fb.width(), fb.height());
    // In bands of rows, one band per item (each pixel's result is its own: the same picture
    // for any number of threads). A tile whose clear is deferred (framebuffer.h) has all its
    // samples one color, the clear's, and that is each of its pixels.
    constexpr int kBandRows = 16;
    const TileGrid& tiles = fb.tiles();
    const int width = fb.width(), bands = (fb.height() + kBandRows - 1) / kBandRows;
    auto run = [&](size_t b, unsigned) {
        for (int y = int(b) * kBandRows; y < std::min(fb.height(), int(b + 1) * kBandRows); ++y)
            for (int tx = 0; tx < tiles.tiles_x; ++tx) {
                const size_t begin = size_t(y) * size_t(width) + size_t(tx * kTileSize);
                const size_t end = size_t(y) * size_t(width) + size_t(std::min(width, (tx + 1) * kTileSize));
                if (const Framebuffer::TileClear* c = fb.deferred(tiles.tile_index(tx, y / kTileSize)))
                    std::fill(img.pixels.begin() + ptrdiff_t(begin), img.pixels.begin() + ptrdiff_t(end), c->color);
                else if (fb.samples() == 1)  // nothing to average
                    std::copy(fb.color_plane() + begin, fb.color_plane() + end, img.pixels.begin() + ptrdiff_t(begin));
                else
                    resolve_pixels(fb, img, begin, end);
            }
    };
    parallel_for(pool, size_t(bands), run);
}

Image downsample_box(const Image& in, int k, ColorSpace color) {
    if (k == 1) return in;
    Image out(in.width / k, in.height / k);
    const auto n = unsigned(k * k);
    const srgb::Tables& tables = srgb::tables();
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            if (color == ColorSpace::Srgb) {
                out.pixels[size_t(y) * size_t(out.width) + size_t(x)] = srgb_mean(tables, n, [&](unsigned i) {
                    return in.pixels[size_t(y * k + int(i) / k) * size_t(in.width) + size_t(x * k + int(i) % k)];
                });
                continue;
            }
            unsigned sum[4] = {n / 2, n / 2, n / 2, n / 2};
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) {
                    const Rgba8 c = in.pixels[size_t(y * k + j) * size_t(in.width) + size_t(x * k + i)];
                    sum[0] += c.r, sum[1] += c.g, sum[2] += c.b, sum[3] += c.a;
                }
            out.pixels[size_t(y) * size_t(out.width) + size_t(x)] = {uint8_t(sum[0] / n), uint8_t(sum[1] / n), uint8_t(sum[2] / n),
                                                                    uint8_t(sum[3] / n)};
        }
    return out;
}

GrayImage<float> depth_picture(const Framebuffer& fb) {
    GrayImage<float> out{fb.width(), fb.height(), std::vector<float>(size_t(fb.width()) * size_t(fb.height()))};
    for (int y = 0; y < fb.height(); ++y)
        for (int x = 0; x < fb.width(); ++x) out.values[size_t(y) * size_t(fb.width()) + size_t(x)] = fb.depth_data()[fb.sample_index(x, y)];
    return out;
}

GrayImage<uint8_t> stencil_picture(const Framebuffer& fb, uint8_t clear) {
    GrayImage<uint8_t> out{fb.width(), fb.height(), std::vector<uint8_t>(size_t(fb.width()) * size_t(fb.height()), clear)};
    if (!fb.has_stencil()) return out;
    for (int y = 0; y < fb.height(); ++y)
        for (int x = 0; x < fb.width(); ++x) out.values[size_t(y) * size_t(fb.width()) + size_t(x)] = fb.stencil_data()[fb.sample_index(x, y)];
    return out;
}

GrayImage<uint16_t> normalize_depth16(const GrayImage<float>& depth) {
    float lo = HUGE_VALF, hi = -HUGE_VALF;
    for (float z : depth.values)
        if (std::isfinite(z)) lo = std::min(lo, z), hi = std::max(hi, z);
    GrayImage<uint16_t> out{depth.width, depth.height, std::vector<uint16_t>(depth.values.size(), 0)};
    if (!(hi > lo)) return out;
    const double scale = 65535.0 / (double(hi) - double(lo));
    for (size_t i = 0; i < depth.values.size(); ++i)
        if (std::isfinite(depth.values[i])) out.values[i] = uint16_t(std::lround((double(depth.values[i]) - lo) * scale));
    return out;
}

Image Framebuffer::read_pixels() const {
    Image img;
    resolve(*this, img);
    return img;
}

}  // namespace softraster
