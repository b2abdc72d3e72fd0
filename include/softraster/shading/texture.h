// Textures and their sampling (docs/scene-format.md "Textures"): 8-bit texels, (0, 0) at the
// bottom-left of the picture as displayed, texel centers at ((i + 0.5) / w, (j + 0.5) / h).
// An sRGB texture (GL_SRGB8_ALPHA8) has its r, g, b encoded; each texel is decoded (srgb.h)
// before it is filtered (and kept decoded: fixed_texels), and its mipmaps are averaged in
// linear light.
//
// A texture keeps its mipmap chain (level k is max(1, w >> k) by max(1, h >> k), each texel
// the average of the 2x2 texels under it, as glGenerateMipmap makes them). A Sampler is
// GL's sampler state: a filter within a level for magnification and one for minification,
// how the levels are chosen (none, nearest, linear: trilinear filtering) and a wrap mode per
// axis (repeat, clamp to edge, mirrored repeat, clamp to a border color).
//
// Which level: from the screen-space derivatives of (u, v) over the pixel's 2x2 quad (GL's
// level of detail, computed as Mesa llvmpipe computes it; select_lod in texture.cpp).
//
// Precision: an 8-bit texture filters in fixed point, as llvmpipe filters 8-bit textures.
// The sample point is cut to 1/256 of a texel, each channel is carried on a scale of 0 to
// 65280 through the bilinear and trilinear blends (value x 256), and the weights are 8 bits
// (the level weight too). Each blend is v - (v w >> 8) + (v' w >> 8), exact for a linear
// texture's rows, where v = 256 a. An sRGB texture's r, g, b are decoded to linear light and
// rounded to the scale (srgb::Tables::decode_fixed), and its sample point and weights have
// 12 bits (1/4096 of a texel): llvmpipe filters sRGB texels in float, and the dark end of
// the sRGB curve would show 8-bit weights' steps (up to 5/255 on its conformance scene).
// The result differs from a float blend by less than 2/65280 for the same weights (3/65280
// for sRGB, its texels rounded). A lookup with a border color filters in float instead.
//
// Anisotropic filtering (GL_TEXTURE_MAX_ANISOTROPY, EXT_texture_filter_anisotropic): where
// the footprint is N times longer than wide (N up to the sampler's limit), N lookups along
// its long axis, each at the level of detail of a footprint N times shorter, averaged.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <glm/ext/vector_int4.hpp>

#include "softraster/image.h"
#include "softraster/pipeline/simd.h"
#include "softraster/srgb.h"

namespace softraster {

namespace lanes {
struct PotLevels;  // (the eight-lane lookup's view of the levels: src/shading/texture_lanes.h)
// The first 16 levels' numbers as lane tables (sample8 picks a level per lane with a
// permute); entries past the last level repeat it. The last five serve the common lookup
// (src/shading/texture_uniform.cpp): in memory, each is one broadcast there, where working
// it out from the sizes would take the shuffle port the texel loads wait on.
struct LevelTables {
    std::array<int32_t, 16> width, height, tiles_x, offset;
    std::array<int32_t, 16> shift_u, shift_v;  // a sample point of level 0 to this level: min(level, log2 side)
    std::array<int32_t, 16> mask_w, mask_h;    // side - 1 (a power-of-two texture's wrap)
    std::array<int32_t, 16> log2_tiles_x;      // (tiles_x, a power of two)
};
}  // namespace lanes

enum class Filter { Nearest, Bilinear };          // within a level: GL_NEAREST, GL_LINEAR
enum class MipFilter { None, Nearest, Linear };  // between levels: ..._MIPMAP_NEAREST, ..._MIPMAP_LINEAR
enum class Wrap { Repeat, Clamp, Mirror, Border };

struct Sampler {
    Filter mag = Filter::Bilinear;
    Filter min = Filter::Bilinear;
    MipFilter mip = MipFilter::None;
    Wrap wrap_s = Wrap::Repeat, wrap_t = Wrap::Repeat;
    glm::vec4 border{0.0f};  // GL_TEXTURE_BORDER_COLOR
    int max_anisotropy = 1;  // GL_TEXTURE_MAX_ANISOTROPY: 1 (off) to 16 probes

    // One filter, no mipmaps, one wrap mode (scene format version 1's choices).
    static Sampler plain(Filter f, Wrap w) { return {f, f, MipFilter::None, w, w, glm::vec4(0.0f)}; }
    // Whether the level of detail changes anything: otherwise level 0 with the one filter.
    bool uses_lod() const { return mip != MipFilter::None || min != mag || max_anisotropy > 1; }
};

// d(u, v)/dx and d(u, v)/dy at a pixel: the differences across its 2x2 quad (GL's coarse
// derivatives; interpolate_varyings in interpolation.h).
struct UvDerivatives {
    float dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
};

// The level(s) a lookup reads, from select_lod.
struct LevelChoice {
    bool minified = false;  // the min filter applies (otherwise the mag filter, on level 0)
    int level0 = 0, level1 = 0;
    float weight = 0.0f;    // of level1 (trilinear)
    // Anisotropic filtering: the number of lookups and the footprint's long axis in (u, v)
    // (the derivative along x or y, whichever is longer); the lookups sit at
    // uv + ((2k + 1) / (2 probes) - 1/2) axis, k = 0 .. probes - 1.
    int probes = 1;
    float axis_u = 0.0f, axis_v = 0.0f;
};

class Texture {
public:
    static constexpr int kMaxSide = 65536;  // texels a side, at most
    static constexpr int kTileSide = 5, kTileTexels = kTileSide * kTileSide;  // (the stored tiles, below)
    // The fixed-point channel value (0 to 65280) to [0, 1]: times 1/255 as an 8-bit texel is
    // converted, and 1/256 (exact), so that value x 256 gives the 8-bit conversion's bits.
    static constexpr float kFixedToUnit = (1.0f / 255.0f) / 256.0f;
    // The fixed-point filter's fraction bits, of the sample point and the weights (above).
    static constexpr int fraction_bits(bool srgb) { return srgb ? 12 : 8; }

    // image row 0 is the top of the picture
    explicit Texture(const Image& image, ColorSpace color = ColorSpace::Linear);

    bool srgb() const { return srgb_; }
    int width() const { return levels_[0].width; }
    int height() const { return levels_[0].height; }
    int levels() const { return int(levels_.size()); }
    int level_width(int level) const { return levels_[size_t(level)].width; }
    int level_height(int level) const { return levels_[size_t(level)].height; }
    // Texel (i, j) of a level, j counted from the bottom row, as floats in [0, 1].
    // (Decoded, for an sRGB texture.)
    glm::vec4 texel(int level, int i, int j) const {
        const uint32_t t = stored_bits(texel_index(levels_[size_t(level)], i, j));
        if (srgb_) return {srgb::decode(uint8_t(t)), srgb::decode(uint8_t(t >> 8)), srgb::decode(uint8_t(t >> 16)), float(t >> 24) * (1.0f / 255.0f)};
        return glm::vec4(float(t & 255u), float((t >> 8) & 255u), float((t >> 16) & 255u), float(t >> 24)) * (1.0f / 255.0f);
    }
    // The stored bytes of a texel (encoded, for an sRGB texture).
    Rgba8 stored(int level, int i, int j) const {
        const uint32_t t = stored_bits(texel_index(levels_[size_t(level)], i, j));
        return {uint8_t(t), uint8_t(t >> 8), uint8_t(t >> 16), uint8_t(t >> 24)};
    }
    glm::vec4 texel(int i, int j) const { return texel(0, i, j); }

    // A lookup where the texture is magnified (level 0, the mag filter).
    glm::vec4 sample(glm::vec2 uv, const Sampler& s) const;
    glm::vec4 sample(glm::vec2 uv, Filter f, Wrap w) const { return sample(uv, Sampler::plain(f, w)); }
    // A lookup with the level of detail from the derivatives.
    glm::vec4 sample(glm::vec2 uv, const UvDerivatives& d, const Sampler& s) const;
    // Eight lookups at once, each as sample() computes it. d: du/dx, dv/dx, du/dy, dv/dy.
    // Out of line: the eight-pixel shaders call it from every tile loop they are inlined
    // into, and one compiled copy (a call per eight texels) keeps the build small.
    void sample8(const simd::f8& u, const simd::f8& v, const std::array<simd::f8, 4>& d, const Sampler& s,
                 std::array<simd::f8, 4>& rgba) const;
    // The lookups of two groups of eight, (u0, v0) with derivatives d0 and (u1, v1) with d1:
    // a row of 2x2 quads' first and second rows (the same derivatives, the quads'), or any
    // two. Each as sample8 computes it; faster together, as the second group's loads need not
    // wait behind the first's filter, and where the derivatives agree one level of detail
    // serves both.
    void sample_pair(const simd::f8& u0, const simd::f8& v0, const simd::f8& u1, const simd::f8& v1, const std::array<simd::f8, 4>& d0,
                     const std::array<simd::f8, 4>& d1, const Sampler& s, std::array<simd::f8, 4>& rgba0, std::array<simd::f8, 4>& rgba1) const;

    // The lookups of four groups of eight: two neighbouring pairs as sample_pair takes
    // them, groups 0 and 1 one pair's rows, 2 and 3 the other's, or any four (each with its
    // own derivatives). Each as sample8 computes it; faster than two pairs, as one call's
    // fixed costs serve all four. Group g's numbers are
    // read where they lie, six vectors in a row from uv[g]: u, v and the derivatives (du/dx,
    // dv/dx, du/dy, dv/dy), as a shader's varyings hold them (SurfaceShader's Varyings), so
    // that the shader need not copy 24 vectors into a call's arguments.
    void sample_four(const simd::f8* const (&uv)[4], const Sampler& s, std::array<simd::f8, 4> (&rgba)[4]) const;

    LevelChoice select_lod(const UvDerivatives& d, const Sampler& s) const;

private:
    // Each level is stored in tiles of 4x4 texels, the tiles row by row, each with an apron:
    // a fifth column and a fifth row repeating the texels to the right and above (the next
    // tiles' first column and row, and past the level's last texel its first, as repeat
    // wraps). A tile is 5x5 texels, rows bottom first, 100 bytes (200 decoded). Every
    // bilinear footprint whose lower-left texel is in the tile is then inside it, at offsets
    // 0, 1, 5 and 6: two 8-byte loads instead of four gathered texels (sample_lanes). A
    // level's sides are padded to multiples of 4 (the padding holds the wrapped texels too).
    // All levels share one array.
    struct Level {
        int width, height;
        int tiles_x;  // tiles per row
        int offset;   // of the level's first texel in the array
    };
    static size_t texel_index(const Level& l, int i, int j) {
        return size_t(l.offset) + size_t((j >> 2) * l.tiles_x + (i >> 2)) * kTileTexels + size_t((j & 3) * kTileSide + (i & 3));
    }
    // A linear texture's texels, r in the low byte (null for an sRGB texture).
    const uint32_t* texels() const { return storage_.data() + aligned_; }
    // An sRGB texture's texels, and only those, decoded onto the fixed-point scale (above): r,
    // g, b, a in the 16-bit quarters from the lowest, in the places texel_index gives. The
    // filters read them as a linear texture's bytes, with no table lookup per channel and
    // texel; the 8-bit copy they were made from is not kept (it would add half their size).
    const uint64_t* fixed_texels() const { return fixed_storage_.data() + fixed_aligned_; }
    // Texel `at`'s stored bytes, r in the low byte, from whichever copy the texture keeps.
    uint32_t stored_bits(size_t at) const {
        if (!srgb_) return texels()[at];
        const uint64_t t = fixed_texels()[at];
        const std::array<uint8_t, 65281>& code = srgb::tables().code_of_fixed;
        return uint32_t(code[t & 0xffffu]) | uint32_t(code[(t >> 16) & 0xffffu]) << 8 | uint32_t(code[(t >> 32) & 0xffffu]) << 16 |
               uint32_t(t >> 56) << 24;  // (alpha: 256 a)
    }
    std::vector<Level> levels_;
    std::vector<uint32_t> storage_;  // (linear textures only)
    size_t aligned_ = 0;              // index of the first texel: at a 64-byte boundary
    std::vector<uint64_t> fixed_storage_;  // (sRGB textures only)
    size_t fixed_aligned_ = 0;
    bool srgb_ = false;
    bool pot_ = false;  // both sides powers of two (then every level's are)
    lanes::LevelTables tables_{};
    template <Filter F>
    glm::vec4 sample_level(int level, glm::vec2 uv, const Sampler& s) const;
    template <Filter F>
    glm::ivec4 sample_level_fixed(int level, glm::vec2 uv, const Sampler& s) const;
    // Whether a lookup filters in fixed point (above).
    bool fixed_point(const Sampler& s) const { return s.wrap_s != Wrap::Border && s.wrap_t != Wrap::Border; }
    template <bool Wide, bool Srgb>
    void sample_lanes(const simd::f8& u, const simd::f8& v, const std::array<simd::f8, 4>& d, const Sampler& s,
                      std::array<simd::f8, 4>& rgba) const;
    lanes::PotLevels pot_levels() const;  // (for the common lookup)
};

namespace detail {
// floor(t) as an int, for any float: NaN and huge values are pinned to a safe range first
// (a float -> int conversion out of range is undefined behaviour).
inline int floor_to_int(float t) {
    if (!(t > -1.0e8f)) return -100000000;
    if (t > 1.0e8f) return 100000000;
    const int i = int(t);
    return float(i) > t ? i - 1 : i;
}
// floor(t) as an int for |t| < 2^31 (a reduced coordinate in fixed-point steps).
inline int floor_bounded(float t) {
    const int i = int(t);
    return float(i) > t ? i - 1 : i;
}
// Coordinate in [0, 1) (repeat), [0, 2) (mirror) or a bounded range (clamp, border) before
// scaling, so that texel arithmetic stays exact and in int range for any uv.
inline float reduce(float u, Wrap w) {
    if (w == Wrap::Repeat || w == Wrap::Mirror) {
        if (!(u >= -1.0e6f && u <= 1.0e6f)) return 0.0f;
        // mirrored repeat: a period of 2 texture widths. (Times 1/period, not divided by
        // it: the same bits for a power of two, without a division per lookup.)
        const bool mirror = w == Wrap::Mirror;
        return u - (mirror ? 2.0f : 1.0f) * float(floor_to_int(u * (mirror ? 0.5f : 1.0f)));
    }
    return u != u ? 0.0f : (u < -1.0f ? -1.0f : (u > 2.0f ? 2.0f : u));
}
// Texel index i along an axis of n texels (GL 4.6, table 8.20), or -1 for the border color.
// Callers pass i in [-1, 2n] (coordinates are reduced first), so no division is needed.
inline int wrap_texel(int i, int n, Wrap w) {
    switch (w) {
        case Wrap::Repeat: return i < 0 ? i + n : (i >= n ? i - n : i);
        case Wrap::Clamp: return i < 0 ? 0 : (i >= n ? n - 1 : i);
        case Wrap::Mirror: {  // period 2n: i, then the axis backwards
            const int m = i < 0 ? i + 2 * n : (i >= 2 * n ? i - 2 * n : i);
            return m < n ? m : 2 * n - 1 - m;
        }
        case Wrap::Border: return i < 0 || i >= n ? -1 : i;
    }
    return 0;
}
}  // namespace detail

}  // namespace softraster
