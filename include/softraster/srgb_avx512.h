// sRGB's exact encode (srgb.h) sixteen lanes at a time, without a table lookup per lane, on
// CPUs with AVX-512 (simd::cpu_has_avx512): how the output merge packs an sRGB framebuffer's
// pixels there.
#pragma once
#include <array>

#include "softraster/pipeline/simd.h"

#if SOFTRASTER_HAS_AVX2_PATH
namespace softraster::srgb {

// Each group's colors as an sRGB framebuffer stores them, the same bits as
// quantize_pack_srgb8 (output_merge.h): r, g, b encoded, alpha quantized, packed into
// out[g] for g < count. Only where simd::cpu_has_avx512() holds.
void pack_groups_avx512(const std::array<simd::f8, 4>* rgba, int count, simd::i8* out);

}  // namespace softraster::srgb
#endif
