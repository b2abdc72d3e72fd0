// Stage 10, resolve: the multisampled buffer becomes the picture.
// Each channel of a pixel is floor(mean + 0.5) of its stored 8-bit samples.
#include <algorithm>

#include "softraster/framebuffer.h"

namespace softraster {

Image Framebuffer::read_pixels() const {
    Image img(width_, height_);
    if (samples_ == 1) {  // nothing to average
        std::copy(color_.begin(), color_.end(), img.pixels.begin());
        return img;
    }
    const int n = samples_;
    for (size_t p = 0; p < img.pixels.size(); ++p) {
        const Rgba8* s = &color_[p * size_t(n)];
        unsigned r = 0, g = 0, b = 0, a = 0;
        for (int i = 0; i < n; ++i) {
            r += s[i].r;
            g += s[i].g;
            b += s[i].b;
            a += s[i].a;
        }
        const unsigned half = unsigned(n) / 2;
        img.pixels[p] = {uint8_t((r + half) / unsigned(n)), uint8_t((g + half) / unsigned(n)),
                         uint8_t((b + half) / unsigned(n)), uint8_t((a + half) / unsigned(n))};
    }
    return img;
}

}  // namespace softraster
