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
