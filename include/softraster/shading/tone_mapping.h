// Exposure and tone mapping: the last step of the fragment shader, from the light a surface
// sends (any value >= 0) to a color the framebuffer can hold (docs/scene-format.md "Color
// spaces"). Per channel of x = exposure * c (alpha is left alone):
//   none:     x
//   Reinhard: x / (1 + x)                                          (Reinhard et al. 2002)
//   ACES:     clamp(x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14), 0, 1)
//             (Narkowicz's 2015 fit of the ACES filmic curve)
// The scalar and the eight-lane forms do the same operations in the same order.
#pragma once
#include <array>
#include <type_traits>

#include <glm/vec4.hpp>

#include "softraster/pipeline/simd.h"

namespace softraster {

enum class ToneCurve { None, Reinhard, Aces };

struct ToneMapping {
    ToneCurve curve = ToneCurve::None;
    float exposure = 1.0f;
    // Whether it changes anything: otherwise the shader skips it.
    bool active() const { return curve != ToneCurve::None || exposure != 1.0f; }
};

// One channel, in place. (By reference, for eight lanes too: a 32-byte vector passed or
// returned by value between the AVX2 copy and code compiled without AVX changes its bits.)
template <class T>
inline void tone_map_channel(ToneCurve curve, float exposure, T& c) {
    const T x = exposure * c;
    switch (curve) {
        case ToneCurve::None: c = x; return;
        case ToneCurve::Reinhard: c = x / (1.0f + x); return;
        case ToneCurve::Aces: {
            const T y = x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f);
            if constexpr (std::is_same_v<T, float>) c = y < 0.0f ? 0.0f : (y > 1.0f ? 1.0f : y);
            else c = simd::clamp01(y);
            return;
        }
    }
}

inline glm::vec4 tone_map(const ToneMapping& t, glm::vec4 c) {
    for (int k = 0; k < 3; ++k) tone_map_channel(t.curve, t.exposure, c[k]);
    return c;
}

inline void tone_map(const ToneMapping& t, std::array<simd::f8, 4>& c) {
    for (size_t k = 0; k < 3; ++k) tone_map_channel(t.curve, t.exposure, c[k]);
}

}  // namespace softraster
