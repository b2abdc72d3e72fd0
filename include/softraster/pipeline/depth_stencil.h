// Stage 9, the depth and stencil tests (early: before the shader, unless a fragment may be
// discarded; general_back_end.h).
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
// With a stencil test (the general back end only, general_back_end.h), each sample first
// compares (ref & read_mask) with (stored & read_mask) by the face's function; a sample that
// fails gets the face's `fail` operation and is not drawn; one that then fails the depth test
// gets `depth_fail`; one that passes both gets `pass` (and its depth written). Operations
// write only the bits of write_mask: stored = (stored & ~write_mask) | (new & write_mask).
// Front and back faces have their own state. The fast back end's single-sampled opaque
// copy checks per draw whether stencil is tested (DepthStencilTest::stencil); its other
// copies, and the hidden-surface passes, run DepthTest alone.
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

// The depth test of one draw (the fast back end's whole depth-stencil stage).
struct DepthTest {
    bool enabled = true;
    DepthFunc func = DepthFunc::Less;
    bool write = true;  // (only when enabled: GL writes no depth with the test off)

    DepthTest() = default;
    explicit DepthTest(const RenderState& st) : enabled(st.depth_test), func(st.depth_func), write(st.depth_test && st.depth_write) {}

    // One sample at depth z against the stored one.
    bool passes(float z, float stored) const { return !enabled || depth_compare(func, z, stored); }

    // Eight samples at depth[at, at + 8) of a row of `width` values, at depths z: returns the
    // lanes of `covered` that pass, and stores their z when the draw writes depth.
    simd::i8 test_group(float* depth, int at, int width, simd::f8 z, simd::i8 covered) const {
        if (!enabled) return covered;
        const simd::f8 stored = simd::load_group<simd::f8>(depth, at, width);
        const simd::i8 pass = covered & depth_compare(func, z, stored);
        if (write) simd::store_group(depth, at, width, simd::select(pass, z, stored));  // (unchanged where none passes)
        return pass;
    }

    // The same for a block of four pixels in each of two rows (rasterize_blocks): lanes 0-3
    // at depth[0, 4), lanes 4-7 at depth[width, width + 4).
    simd::i8 test_block(float* depth, int width, simd::f8 z, simd::i8 covered) const {
        if (!enabled) return covered;
        const simd::f8 stored = simd::load_halves(depth, depth + width);
        const simd::i8 pass = covered & depth_compare(func, z, stored);
        if (write) simd::store_halves(depth, depth + width, simd::select(pass, z, stored));  // (unchanged where none passes)
        return pass;
    }

    // The samples of one pixel in mask `covered`, at depths z[s]: returns those that pass,
    // writing nothing.
    template <int Samples>
    unsigned test_pixel(const float* depth, unsigned covered, const float* z) const {
        unsigned pass = 0;
        for (int s = 0; s < Samples; ++s)
            if ((covered & (1u << s)) && passes(z[s], depth[s])) pass |= 1u << s;
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

// The stencil value after operation `op` (before the write mask), for one value (T = int
// or uint8_t) or eight (T = simd::i8, lane by lane): the same code either way, all in 0..255.
template <class T>
inline T stencil_op_result(StencilOp op, T stored, T ref) {
    const T zero{}, top = zero + 255;
    switch (op) {
        case StencilOp::Keep: return stored;
        case StencilOp::Zero: return zero;
        case StencilOp::Replace: return ref;
        case StencilOp::Incr: return stored < top ? T(stored + 1) : top;
        case StencilOp::IncrWrap: return T((stored + 1) & 255);
        case StencilOp::Decr: return stored > zero ? T(stored - 1) : zero;
        case StencilOp::DecrWrap: return T((stored - 1) & 255);
        case StencilOp::Invert: return T(~stored & 255);
    }
    return stored;
}
inline void apply_stencil_op(const StencilFace& f, StencilOp op, uint8_t& stored) {
    stored = uint8_t((stored & ~f.write_mask) | (stencil_op_result<uint8_t>(op, stored, f.ref) & f.write_mask));
}

// The depth and stencil tests of one draw, sample by sample.
struct DepthStencilTest {
    DepthTest depth;
    bool stencil = false;
    StencilFace front, back;
    // Whether a face's operations may change a stored value: not when all three keep it, or
    // the write mask is 0 (then test_group stores nothing).
    bool front_writes = false, back_writes = false;
    static bool writes(const StencilFace& f) {
        const bool keeps = f.fail == StencilOp::Keep && f.depth_fail == StencilOp::Keep && f.pass == StencilOp::Keep;
        return f.write_mask != 0 && !keeps;
    }

    DepthStencilTest() = default;
    explicit DepthStencilTest(const DepthTest& d) : depth(d) {}  // no stencil test
    explicit DepthStencilTest(const RenderState& st)
        : depth(st), stencil(st.stencil_test), front(st.stencil_front), back(st.stencil_back),
          front_writes(writes(st.stencil_front)), back_writes(writes(st.stencil_back)) {}

    // The samples of one pixel in `covered` (of `samples`), at depths z[s]: tests, stencil
    // operations and depth writes in GL's order; returns the samples that pass both tests.
    unsigned test_and_write(float* stored_z, uint8_t* stored_stencil, int samples, unsigned covered, const float* z,
                            bool front_facing) const {
        const StencilFace& f = front_facing ? front : back;
        unsigned pass = 0;
        for (int s = 0; s < samples; ++s) {
            if (!(covered & (1u << s))) continue;
            if (stencil) {
                uint8_t& st = stored_stencil[s];
                if (!depth_compare(f.func, unsigned(f.ref & f.read_mask), unsigned(st & f.read_mask))) {
                    apply_stencil_op(f, f.fail, st);
                    continue;
                }
            }
            const bool depth_pass = depth.passes(z[s], stored_z[s]);
            if (stencil) apply_stencil_op(f, depth_pass ? f.pass : f.depth_fail, stored_stencil[s]);
            if (!depth_pass) continue;
            depth.write_pixel<1>(stored_z + s, 1u, z + s);
            pass |= 1u << s;
        }
        return pass;
    }

    // The same for eight single-sampled pixels at depth[at, at + 8) and stencil[at, at + 8)
    // of a row of `width` (the fast back end's groups, tile_back_end.h): returns the lanes of
    // `covered` that pass both tests.
    simd::i8 test_group(float* depth_row, uint8_t* stencil_row, int at, int width, simd::f8 z, simd::i8 covered,
                        bool front_facing) const {
        using simd::i8;
        if (!stencil) return depth.test_group(depth_row, at, width, z, covered);  // (there may be no stencil buffer)
        const StencilFace& f = front_facing ? front : back;
        const i8 stored = simd::load_bytes(stencil_row, at, width);
        const i8 read = simd::splat_i(f.read_mask), ref = simd::splat_i(f.ref);
        const i8 stencil_pass = covered & depth_compare(f.func, ref & read, stored & read);
        // The depth test (and write) of the lanes that passed the stencil test.
        const i8 pass = depth.test_group(depth_row, at, width, z, stencil_pass);
        if (!(front_facing ? front_writes : back_writes)) return pass;  // (every operation keeps the value, or none may write)
        // Each lane's operation: fail where the stencil test failed, depth fail, pass, or none.
        const i8 result = simd::select(covered & ~stencil_pass, stencil_op_result(f.fail, stored, ref),
                                       simd::select(stencil_pass & ~pass, stencil_op_result(f.depth_fail, stored, ref),
                                                    simd::select(pass, stencil_op_result(f.pass, stored, ref), stored)));
        const i8 write = simd::splat_i(f.write_mask);
        const i8 updated = (stored & ~write) | (result & write);
        simd::store_bytes(stencil_row, at, width, updated);
        return pass;
    }
};

}  // namespace softraster
