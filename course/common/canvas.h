// The pixel device the first lessons draw on: a picture and a function that sets one pixel,
// which is how the tutorials start (the book's "pixel device", tinyrenderer's TGAImage).
// Everything else in the course is built on top of set() until lesson 10 hands the work to
// the real pipeline.
#pragma once
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <initializer_list>

#include <glm/vec4.hpp>

#include "softraster/image.h"
#include "softraster/io/image_io.h"

namespace course {

struct Color {
    uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Color&, const Color&) = default;
};

inline constexpr Color kBlack{0, 0, 0}, kWhite{255, 255, 255}, kRed{230, 60, 50}, kGreen{70, 190, 90}, kBlue{60, 110, 230},
    kYellow{240, 200, 60}, kGray{110, 110, 110}, kDark{28, 30, 36};

// A color as the pipeline's clear takes it (lessons 10 on clear to the canvas's background).
inline glm::vec4 clear_color(Color c) { return {float(c.r) / 255.0f, float(c.g) / 255.0f, float(c.b) / 255.0f, 1.0f}; }

class Canvas {
public:
    Canvas(int width, int height, Color background = kDark) : image_(width, height) {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) set(x, y, background);
    }
    int width() const { return image_.width; }
    int height() const { return image_.height; }

    // (0, 0) is the top-left pixel, x to the right, y down. Pixels outside are ignored, so a
    // lesson may draw past the edges.
    void set(int x, int y, Color c) {
        if (x < 0 || y < 0 || x >= width() || y >= height()) return;
        image_.at(x, y) = {c.r, c.g, c.b, 255};
    }
    Color get(int x, int y) const {
        const softraster::Rgba8 p = image_.at(x, y);
        return {p.r, p.g, p.b};
    }

    // Writes a PNG in which each pixel is a zoom x zoom square, so that the pixels of a small
    // picture can be seen; from zoom 6 on, a thin dark line separates them.
    void save(const std::filesystem::path& path, int zoom = 1) const {
        softraster::Image big(width() * zoom, height() * zoom);
        for (int y = 0; y < big.height; ++y)
            for (int x = 0; x < big.width; ++x) {
                softraster::Rgba8 p = image_.at(x / zoom, y / zoom);
                if (zoom >= 6 && (x % zoom == 0 || y % zoom == 0)) p = {uint8_t(p.r * 3 / 4), uint8_t(p.g * 3 / 4), uint8_t(p.b * 3 / 4), 255};
                big.at(x, y) = p;
            }
        softraster::write_png(big, path);
    }
    const softraster::Image& image() const { return image_; }

private:
    softraster::Image image_;
};

// A picture the pipeline made (lessons 10 on), as a canvas.
inline Canvas to_canvas(const softraster::Image& image) {
    Canvas c(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) c.set(x, y, {image.at(x, y).r, image.at(x, y).g, image.at(x, y).b});
    return c;
}

// Pictures side by side (top-aligned), with `gap` pixels of `background` between them: the
// comparisons of the lessons.
inline Canvas beside(std::initializer_list<const Canvas*> parts, int gap = 2, Color background = kBlack) {
    int width = 0, height = 0;
    for (const Canvas* c : parts) width += c->width() + (width ? gap : 0), height = std::max(height, c->height());
    Canvas out(width, height, background);
    int at = 0;
    for (const Canvas* c : parts) {
        for (int y = 0; y < c->height(); ++y)
            for (int x = 0; x < c->width(); ++x) out.set(at + x, y, c->get(x, y));
        at += c->width() + gap;
    }
    return out;
}

}  // namespace course
