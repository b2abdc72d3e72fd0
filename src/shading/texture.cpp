#include "softraster/shading/texture.h"

#include <stdexcept>

namespace softraster {

Texture::Texture(const Image& image) : width_(image.width), height_(image.height) {
    if (width_ < 1 || height_ < 1) throw std::invalid_argument("texture image is empty");
    texels_.resize(size_t(width_) * size_t(height_));
    for (int j = 0; j < height_; ++j)  // flip: texel row 0 is the bottom of the picture
        for (int i = 0; i < width_; ++i) texels_[size_t(j) * size_t(width_) + size_t(i)] = image.at(i, height_ - 1 - j);
}

}  // namespace softraster

namespace softraster {
namespace {
// flatten: the lookup inlined into the lane loop (left to itself GCC calls it per lane).
template <Filter F, Wrap W>
[[gnu::flatten]] void sample_lanes(const Texture& t, const simd::f8& u, const simd::f8& v, std::array<simd::f8, 4>& rgba) {
    for (int l = 0; l < simd::kLanes; ++l) {
        const glm::vec4 c = t.sample<F, W>(glm::vec2(u[l], v[l]));
        for (int k = 0; k < 4; ++k) rgba[size_t(k)][l] = c[k];
    }
}
}  // namespace

// In the CPU's best copy (simd.h): with AVX2 the eight lookups vectorize (gathers).
void Texture::sample8(const simd::f8& u, const simd::f8& v, Filter f, Wrap w, std::array<simd::f8, 4>& rgba) const {
    simd::on_best_path([&]<bool>() {
        if (f == Filter::Nearest) {
            if (w == Wrap::Repeat) sample_lanes<Filter::Nearest, Wrap::Repeat>(*this, u, v, rgba);
            else sample_lanes<Filter::Nearest, Wrap::Clamp>(*this, u, v, rgba);
        } else {
            if (w == Wrap::Repeat) sample_lanes<Filter::Bilinear, Wrap::Repeat>(*this, u, v, rgba);
            else sample_lanes<Filter::Bilinear, Wrap::Clamp>(*this, u, v, rgba);
        }
    });
}

}  // namespace softraster
