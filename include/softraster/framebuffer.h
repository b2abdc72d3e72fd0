// The render target: per-sample RGBA8 color, 32-bit float depth and, when a draw uses it,
// an 8-bit stencil value, in flat arrays.
//
// Sample s of pixel (x, y) lives at index (y * width + x) * samples + s, so the samples of a
// pixel are adjacent (one cache line for 4x MSAA color) and a single-sampled buffer is a
// plain image. Colors are stored quantized to 8 bits, as in a GL_RGBA8 attachment, or with
// r, g, b sRGB-encoded, as in a GL_SRGB8_ALPHA8 one with GL_FRAMEBUFFER_SRGB on (srgb.h).
//
// A clear of a whole tile may be deferred, as tiled GPUs do a "fast clear": the tile's
// values are recorded, and its samples written only when something draws there or reads
// them (Framebuffer's deferred clears, below).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <glm/vec4.hpp>

#include "softraster/cache_line_allocator.h"
#include "softraster/image.h"
#include "softraster/pipeline/pipeline_types.h"
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

class Framebuffer {
public:
    static constexpr int kMaxSize = 16384;

    Framebuffer(int width, int height, int samples = 1, ColorSpace color = ColorSpace::Linear)
        : width_(width), height_(height), samples_(samples), color_space_(color), tiles_(width, height) {
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

    void clear_color(const glm::vec4& c) {
        settle();
        std::fill(color_.begin(), color_.end(), quantize_rgba8(c, color_space_));
    }
    void clear_depth(float z = 1.0f) {
        settle();
        std::fill(depth_.begin(), depth_.end(), z);
    }

    // The stencil buffer exists once asked for (Context does when a draw tests stencil),
    // cleared to 0; clears set it from then on.
    bool has_stencil() const { return !stencil_.empty(); }
    void add_stencil() {
        if (!stencil_.empty()) return;
        settle();  // (a clear deferred before the stencil existed did not clear it)
        stencil_.resize(color_.size(), 0);
    }

    size_t sample_index(int x, int y, int s = 0) const {
        return (size_t(y) * size_t(width_) + size_t(x)) * size_t(samples_) + size_t(s);
    }
    // The samples, every deferred clear written first.
    Rgba8* color_data() { return settle(), color_.data(); }
    float* depth_data() { return settle(), depth_.data(); }
    uint8_t* stencil_data() { return settle(), stencil_.data(); }
    const Rgba8* color_data() const { return settle(), color_.data(); }
    const float* depth_data() const { return settle(), depth_.data(); }
    const uint8_t* stencil_data() const { return settle(), stencil_.data(); }

    // ---- Deferred clears
    //
    // A tile cleared whole (color, depth and stencil) keeps only the values until the first
    // draw in it settles it; a tile nothing draws in is never written, and the resolve takes
    // its pixels from the record (a 64x64 tile of 4x MSAA is 128 KB of color and depth).
    // The back end works on tiles each owned by one thread, so it reaches the samples
    // through the planes below, which leave other tiles' records alone; the accessors above
    // settle every tile, for whoever reads the buffer after the frame.
    struct TileClear {
        Rgba8 color{};
        float depth = 1.0f;
        uint8_t stencil = 0;
        bool pending = false;
    };
    const TileGrid& tiles() const { return tiles_; }
    // Sizes the records (on one thread, before the tiles are drawn in parallel).
    void allow_deferred_clears() {
        if (records_.empty()) records_.assign(size_t(tiles_.count()), TileClear{});
    }
    // Tile t's clear, deferred where allow_deferred_clears was called, else written at once.
    void clear_tile(int t, Rgba8 color, float depth, uint8_t stencil) {
        if (records_.empty()) return fill_tile(tiles_.tile_rect(t), &color, depth, &stencil);
        records_[size_t(t)] = {color, depth, stencil, true};
    }
    void clear_tile_depth(int t, float depth) {
        if (!records_.empty() && records_[size_t(t)].pending) {
            records_[size_t(t)].depth = depth;
            return;
        }
        fill_tile(tiles_.tile_rect(t), nullptr, depth, nullptr);
    }
    // Writes tile t's deferred clear, if it has one (by the thread that owns the tile).
    void settle_tile(int t) {
        if (records_.empty() || !records_[size_t(t)].pending) return;
        TileClear& c = records_[size_t(t)];
        fill_tile(tiles_.tile_rect(t), &c.color, c.depth, &c.stencil);
        c.pending = false;
    }
    // Tile t's deferred clear, or null if its samples hold its pixels.
    const TileClear* deferred(int t) const { return records_.empty() || !records_[size_t(t)].pending ? nullptr : &records_[size_t(t)]; }
    // The planes as they are, for the owner of a settled tile (the back end).
    Rgba8* color_plane() { return color_.data(); }
    float* depth_plane() { return depth_.data(); }
    uint8_t* stencil_plane() { return stencil_.data(); }
    const Rgba8* color_plane() const { return color_.data(); }

    // Single-sampled picture of the buffer: the resolve stage for MSAA (see resolve.h).
    Image read_pixels() const;

private:
    // Every deferred clear written. A const reader settles too: the clear has happened, only
    // its values are not yet in the samples. (Well defined: only a buffer that is not const
    // can have a deferred clear. Not for readers on several threads at once while a clear is
    // deferred, which the back end and the resolve are not: they read the planes.)
    void settle() const {
        if (records_.empty()) return;
        for (int t = 0; t < tiles_.count(); ++t) const_cast<Framebuffer*>(this)->settle_tile(t);
        records_.clear();
    }
    // Rows of r: color (unless null), depth, and stencil where there is one (unless null).
    void fill_tile(const Rect& r, const Rgba8* color, float depth, const uint8_t* stencil);

    int width_, height_, samples_;
    ColorSpace color_space_;
    TileGrid tiles_;
    std::vector<Rgba8, CacheLineAllocator<Rgba8>> color_;
    std::vector<float, CacheLineAllocator<float>> depth_;
    std::vector<uint8_t, CacheLineAllocator<uint8_t>> stencil_;
    mutable std::vector<TileClear> records_;  // per tile; empty: no clear deferred
};

}  // namespace softraster
