// Stage 11, fragment shading, for small triangles: fragments that passed the depth test wait
// in a queue and are shaded eight at a time, whichever triangles they came from.
//
// A triangle of a pixel or two fills one or two lanes of a row's group of eight; shaded
// group by group, most of the eight-lane shader's work would be thrown away (a million-
// triangle mesh at 1080p averages about one pixel per triangle). Queued, every shader call
// has eight real fragments. This is the "quad packing" of Masked Software Occlusion
// Culling's and Larrabee's renderers, applied per pixel: the interpolated varyings
// travel with each fragment, so the shader does not need to know its triangle.
//
// The picture is the same as shading each triangle at once, for an opaque draw whose shader
// never discards (kPure, hidden_surface_removal.h) and writes color:
// - depth is tested and written when a fragment is queued, in draw order;
// - colors are written in queue order, which is draw order, one fragment after another,
//   so where two queued fragments hit the same pixel the later one still lands last;
// - opaque colors do not depend on what they overwrite, so writing them later changes nothing.
// Whoever owns the tile flushes the queue before anything else draws in it.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

#include "softraster/framebuffer.h"
#include "softraster/pipeline/output_merge.h"
#include "softraster/pipeline/shader_layout.h"
#include "softraster/pipeline/simd.h"

namespace softraster {

namespace detail {
// For each 8-bit lane mask, the lane indices of its set bits first (in order): a vector
// permuted by it has the selected lanes at the front (a "compress", which AVX2 lacks).
inline constexpr std::array<std::array<int32_t, simd::kLanes>, 256> kCompressLanes = [] {
    std::array<std::array<int32_t, simd::kLanes>, 256> table{};
    for (unsigned m = 0; m < 256; ++m) {
        int n = 0;
        for (int l = 0; l < simd::kLanes; ++l)
            if (m & (1u << l)) table[m][size_t(n++)] = l;
        for (; n < simd::kLanes; ++n) table[m][size_t(n)] = 0;
    }
    return table;
}();
}  // namespace detail

template <int N, int Samples>
class FragmentQueue {
public:
    using ShadeGroups = void (*)(const void*, FragmentGroups<N>&);

    // Starts queueing for the shader whose batch entry is `shade` into `fb` (the queue is empty).
    void start(ShadeGroups shade_groups, const void* shader, Framebuffer& fb) {
        shade_ = shade_groups;
        shader_ = shader;
        color_ = fb.color_plane();
        color_space_ = fb.color_space();
        count_ = 0;
    }

    // The facing of the triangle whose fragments come next. The shader sees one facing per
    // call: a change of facing flushes. (Once per triangle, not per push.)
    void begin_triangle(bool front_facing) {
        if (front_facing != front_facing_ && count_ > 0) flush();
        front_facing_ = front_facing;
    }

    // Queues the lanes of `pass` out of eight fragments of the triangle begun last: window
    // depths z, varyings (already divided by w), index of each pixel's first sample and the
    // samples it writes.
    void push(simd::i8 pass, simd::f8 z, const std::array<simd::f8, N>& var, simd::i8 pixel, simd::i8 samples) {
        using namespace simd;
        const unsigned m = bits(pass);
        i8 lanes;
        std::memcpy(&lanes, detail::kCompressLanes[m].data(), sizeof lanes);
        auto put = [&](auto* dst, auto v) {  // a whole vector: the queue has room for eight past count_
            const auto packed = m == 0xffu ? v : permute(v, lanes);
            std::memcpy(dst + count_, &packed, sizeof packed);
        };
        put(z_.data(), z);
        for (size_t k = 0; k < size_t(N); ++k) put(var_[k].data(), var[k]);
        put(pixel_.data(), pixel);
        if constexpr (Samples > 1) put(samples_.data(), samples);
        count_ += __builtin_popcount(m);
        if (count_ >= kCapacity) drain();
    }

    // Shades and writes everything queued.
    void flush() {
        shade(count_);
        count_ = 0;
    }

private:
    static constexpr int kCapacity = 8 * simd::kLanes;
    static_assert(kCapacity / simd::kLanes <= FragmentGroups<N>::kCapacity, "one call shades a full queue");
    static constexpr size_t kSlots = size_t(kCapacity + simd::kLanes);

    // Shades the full groups of eight and moves what is left (fewer than eight) to the front.
    void drain() {
        const int full = count_ - count_ % simd::kLanes;
        shade(full);
        const size_t rest = size_t(count_ - full), from = size_t(full);
        std::copy_n(z_.begin() + from, rest, z_.begin());
        for (auto& v : var_) std::copy_n(v.begin() + from, rest, v.begin());
        std::copy_n(pixel_.begin() + from, rest, pixel_.begin());
        std::copy_n(samples_.begin() + from, rest, samples_.begin());
        count_ = int(rest);
    }

    // Shades fragments [0, count) with one call, eight to a group, and writes their colors in
    // queue order.
    void shade(int count) {
        using namespace simd;
        if (count == 0) return;
        FragmentGroups<N>& b = batch_;
        b.count = (count + kLanes - 1) / kLanes;
        b.front_facing = front_facing_;
        for (int g = 0; g < b.count; ++g) {
            const int first = g * kLanes, n = std::min(kLanes, count - first);
            const i8 real = kLaneIndex < n;
            // Lanes past the last fragment get the group's first one's inputs: the shader then
            // only sees values it could see anyway (a texture lookup at an arbitrary position
            // would not be).
            auto load = [&](const std::array<float, kSlots>& a) {
                f8 v;
                std::memcpy(&v, a.data() + first, sizeof v);
                return n == kLanes ? v : select(real, v, splat(v[0]));
            };
            for (size_t k = 0; k < size_t(N); ++k) b.varyings[g][k] = load(var_[k]);
            b.z[g] = load(z_);
        }
        shade_(shader_, b);
        i8 packed_groups[GroupPlaces::kCapacity];
        quantize_pack_groups<SOFTRASTER_HAS_AVX2_PATH>(b.rgba, b.count, color_space_, packed_groups);  // (the queue runs in the AVX2 copy only)
        for (int g = 0; g < b.count; ++g) {
            const int first = g * kLanes, n = std::min(kLanes, count - first);
            const i8& packed = packed_groups[g];
            for (int l = 0; l < n; ++l) {
                const size_t slot = size_t(first + l);
                Rgba8 c;
                std::memcpy(&c, reinterpret_cast<const char*>(&packed) + 4 * l, 4);
                Rgba8* dst = color_ + pixel_[slot];
                if constexpr (Samples == 1) {
                    *dst = c;
                } else if constexpr (Samples == 4) {
                    // The pixel's four samples as one vector, the written ones replaced: no
                    // branch per sample, whose outcome changes from pixel to pixel at edges.
                    simd::u4 old;
                    std::memcpy(&old, dst, sizeof old);
                    const simd::u4 color = simd::u4{} + uint32_t(packed[l]);
                    const simd::u4 written = (simd::u4{1, 2, 4, 8} & uint32_t(samples_[slot])) != 0;  // (true: all ones)
                    const simd::u4 out = (old & ~written) | (color & written);
                    std::memcpy(static_cast<void*>(dst), &out, sizeof out);
                } else {
                    for (int s = 0; s < Samples; ++s)
                        if (samples_[slot] & (1 << s)) dst[s] = c;
                }
            }
        }
    }

    ShadeGroups shade_ = nullptr;
    const void* shader_ = nullptr;
    Rgba8* color_ = nullptr;
    ColorSpace color_space_ = ColorSpace::Linear;
    int count_ = 0;
    bool front_facing_ = true;
    // Not initialized: slots are written before they are read (lanes past the last fragment
    // are read but replaced before use, see shade()).
    alignas(32) std::array<float, kSlots> z_;
    alignas(32) std::array<std::array<float, kSlots>, size_t(N)> var_;
    alignas(32) std::array<int32_t, kSlots> pixel_;
    alignas(32) std::array<int32_t, kSlots> samples_;
    FragmentGroups<N> batch_;
};

}  // namespace softraster
