// An 8-bit RGBA picture, row 0 at the top: what a render produces and a PNG stores.
#pragma once
#include <cstdint>
#include <vector>

namespace softraster {

struct Rgba8 {
    uint8_t r = 0, g = 0, b = 0, a = 0;
    friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

struct Image {
    int width = 0;
    int height = 0;
    std::vector<Rgba8> pixels;  // width * height, row-major, row 0 at the top

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h)) {}
    Rgba8& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    const Rgba8& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

// One channel of `width` x `height` values, row 0 at the top (depth and stencil pictures).
template <class T>
struct GrayImage {
    int width = 0, height = 0;
    std::vector<T> values;
};

}  // namespace softraster
