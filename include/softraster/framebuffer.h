// The render target: per-sample RGBA8 color, 32-bit float depth and, when a draw uses it,
// an 8-bit stencil value, in flat arrays.
//
// Sample s of pixel (x, y) lives at index (y * width + x) * samples + s, so the samples of a
// pixel are adjacent (one cache line for 4x MSAA color) and a single-sampled buffer is a
// plain image. Colors are stored quantized to 8 bits, as in a GL_RGBA8 attachment, or with
// r, g, b sRGB-encoded, as in a GL_SRGB8_ALPHA8 one with GL_FRAMEBUFFER_SRGB on (srgb.h).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <vector>

#include <glm/vec4.hpp>

#include "softraster/image.h"
#include "softraster/srgb.h"

namespace softraster {

// floor(255 * clamp(c, 0, 1) + 0.5): the spec's float -> 8-bit conversion. NaN becomes 0.
inline uint8_t quantize_unorm8(float c) {
    if (!(c > 0.0f)) return 0;
    if (c >= 1.0f) return 255;
    return static_cast<uint8_t>(static_cast<int>(255.0f * c + 0.5f));  // positive: truncation is floor
}

inline Rgba8 quantize_rgba8(const glm::vec4& c) {
    return {quantize_unorm8(c.r), quantize_unorm8(c.g), quantize_unorm8(c.b), quantize_unorm8(c.a)};
}

// A color as a framebuffer of that color space stores it: sRGB encodes r, g, b (alpha stays
// linear).
inline Rgba8 quantize_rgba8(const glm::vec4& c, ColorSpace space) {
    if (space == ColorSpace::Linear) return quantize_rgba8(c);
    return {srgb::encode(c.r), srgb::encode(c.g), srgb::encode(c.b), quantize_unorm8(c.a)};
}

// Storage that starts on a cache line. Threads draw different tiles at once (64 pixels
// wide, 256 bytes of color and of depth a row): with each plane starting on a line, as do
// its rows where a row's bytes are a multiple of 64, no line holds two tiles' pixels, which
// would bounce between the cores' caches (a large std::vector's data sits 16 bytes past a
// page start).
template <class T>
struct CacheLineAllocator {
    using value_type = T;
    static constexpr std::align_val_t kLine{64};
    CacheLineAllocator() = default;
    template <class U>
    CacheLineAllocator(const CacheLineAllocator<U>&) {}
    T* allocate(size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kLine)); }
    void deallocate(T* p, size_t) { ::operator delete(p, kLine); }
    bool operator==(const CacheLineAllocator&) const = default;
};

class Framebuffer {
public:
    static constexpr int kMaxSize = 16384;

    Framebuffer(int width, int height, int samples = 1, ColorSpace color = ColorSpace::Linear)
        : width_(width), height_(height), samples_(samples), color_space_(color) {
        if (width < 1 || height < 1 || width > kMaxSize || height > kMaxSize)
            throw std::invalid_argument("framebuffer size must be 1..16384 in each direction");
        if (!valid_samples(samples)) throw std::invalid_argument("samples must be 1, 2, 4, 8 or 16");
        const size_t n = size_t(width) * size_t(height) * size_t(samples);
        color_.resize(n);
        depth_.resize(n, 1.0f);
    }

    static constexpr bool valid_samples(int n) { return n == 1 || n == 2 || n == 4 || n == 8 || n == 16; }

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }
    ColorSpace color_space() const { return color_space_; }
    bool srgb() const { return color_space_ == ColorSpace::Srgb; }

    void clear_color(const glm::vec4& c) { std::fill(color_.begin(), color_.end(), quantize_rgba8(c, color_space_)); }
    void clear_depth(float z = 1.0f) { std::fill(depth_.begin(), depth_.end(), z); }

    // The stencil buffer exists once asked for (Context does when a draw tests stencil),
    // cleared to 0; clears set it from then on.
    bool has_stencil() const { return !stencil_.empty(); }
    void add_stencil() {
        if (stencil_.empty()) stencil_.resize(color_.size(), 0);
    }
    uint8_t* stencil_data() { return stencil_.data(); }
    const uint8_t* stencil_data() const { return stencil_.data(); }

    size_t sample_index(int x, int y, int s = 0) const {
        return (size_t(y) * size_t(width_) + size_t(x)) * size_t(samples_) + size_t(s);
    }
    Rgba8* color_data() { return color_.data(); }
    float* depth_data() { return depth_.data(); }
    const Rgba8* color_data() const { return color_.data(); }
    const float* depth_data() const { return depth_.data(); }

    // Single-sampled picture of the buffer: the resolve stage for MSAA (see resolve.h).
    Image read_pixels() const;

private:
    int width_, height_, samples_;
    ColorSpace color_space_;
    std::vector<Rgba8, CacheLineAllocator<Rgba8>> color_;
    std::vector<float, CacheLineAllocator<float>> depth_;
    std::vector<uint8_t, CacheLineAllocator<uint8_t>> stencil_;
};

}  // namespace softraster
