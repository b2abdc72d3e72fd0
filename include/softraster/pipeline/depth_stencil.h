// Stage 9a, the depth test (the depth-stencil stage: a stencil test joins it here).
//
// Each covered sample's interpolated window depth z is compared with the depth stored for
// that sample, by one of GL's eight functions; a sample that fails is not drawn. Where a
// sample passes and the draw writes depth, z replaces the stored value.
//
// It runs before the fragment shader (early depth): shaders here cannot change depth, so
// the picture is the same, and hidden fragments cost no shading. A shader that may discard
// must not leave depth behind for a fragment it drops, so its draw tests first and writes
// after shading (test_pixel, then write_pixel); every other draw tests and writes at once.
//
// The back end takes this stage's state as a template parameter (DepthStencil), so that
// draws whose state has no stencil pay nothing for it.
#pragma once
#include <cstdint>

#include "softraster/pipeline/simd.h"
#include "softraster/render_state.h"

namespace softraster {

// z against the stored depth, for one sample (float -> bool) or eight (f8 -> lane mask).
template <class T>
inline auto depth_compare(DepthFunc f, T z, T stored) -> decltype(z < stored) {
    using Mask = decltype(z < stored);
    switch (f) {
        case DepthFunc::Never: return Mask{};
        case DepthFunc::Less: return z < stored;
        case DepthFunc::Equal: return z == stored;
        case DepthFunc::LessEqual: return z <= stored;
        case DepthFunc::Greater: return z > stored;
        case DepthFunc::NotEqual: return z != stored;
        case DepthFunc::GreaterEqual: return z >= stored;
        case DepthFunc::Always: return Mask((z == z) | (z != z));  // true in every lane, NaN too
    }
    return Mask{};
}

// The depth test of one draw.
struct DepthTest {
    bool enabled = true;
    DepthFunc func = DepthFunc::Less;
    bool write = true;  // (only when enabled: GL writes no depth with the test off)

    DepthTest() = default;
    explicit DepthTest(const RenderState& st) : enabled(st.depth_test), func(st.depth_func), write(st.depth_test && st.depth_write) {}

    // Eight samples at depth[at, at + 8) of a row of `width` values, at depths z: returns the
    // lanes of `covered` that pass, and stores their z when the draw writes depth.
    simd::i8 test_group(float* depth, int at, int width, simd::f8 z, simd::i8 covered) const {
        if (!enabled) return covered;
        const simd::f8 stored = simd::load_group<simd::f8>(depth, at, width);
        const simd::i8 pass = covered & depth_compare(func, z, stored);
        if (write) simd::store_group(depth, at, width, simd::select(pass, z, stored));  // (unchanged where none passes)
        return pass;
    }

    // The samples of one pixel in mask `covered`, at depths z[s]: returns those that pass,
    // writing nothing.
    template <int Samples>
    unsigned test_pixel(const float* depth, unsigned covered, const float* z) const {
        if (!enabled) return covered;
        unsigned pass = 0;
        for (int s = 0; s < Samples; ++s)
            if ((covered & (1u << s)) && depth_compare(func, z[s], depth[s])) pass |= 1u << s;
        return pass;
    }
    // Stores z[s] for the samples in `pass` (which passed test_pixel), if the draw writes depth.
    template <int Samples>
    void write_pixel(float* depth, unsigned pass, const float* z) const {
        if (!write) return;
        for (int s = 0; s < Samples; ++s)
            if (pass & (1u << s)) depth[s] = z[s];
    }
    // Both at once, for draws whose fragments are never discarded.
    template <int Samples>
    unsigned test_and_write_pixel(float* depth, unsigned covered, const float* z) const {
        const unsigned pass = test_pixel<Samples>(depth, covered, z);
        write_pixel<Samples>(depth, pass, z);
        return pass;
    }
};

}  // namespace softraster
