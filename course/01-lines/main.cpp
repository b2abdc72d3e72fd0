// Lesson 1: pixels and lines. Draws the same fan of lines with DDA and with Bresenham, and
// marks where the two disagree; then one line as the GPU pipeline draws it.
#include "../common/canvas.h"
#include "../common/lesson.h"
#include "../common/pipeline.h"
#include "lines.h"

using namespace course;

int main(int argc, char** argv) {
    const auto out = output_folder(argc, argv);
    // A fan: from the center to every sixth pixel of the border, in all eight octants. The
    // border pixels are an odd number of pixels off the center's row and column, so every
    // line passes exactly between two pixels halfway along (a tie).
    constexpr int kSize = 41, kCenter = 20;
    Canvas dda(kSize, kSize), bresenham(kSize, kSize), differ(kSize, kSize);
    auto fan = [&](auto&& each_line) {
        for (int t = 1; t < kSize - 1; t += 6) {
            each_line(t, 0), each_line(kSize - 1, t), each_line(kSize - 1 - t, kSize - 1), each_line(0, kSize - 1 - t);
        }
    };
    fan([&](int x, int y) {
        line_dda(kCenter, kCenter, x, y, [&](int px, int py) { dda.set(px, py, kYellow); });
        line_bresenham(kCenter, kCenter, x, y, [&](int px, int py) { bresenham.set(px, py, kYellow); });
    });
    // Gray where both set the pixel, red where only DDA did, blue where only Bresenham did.
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const bool a = dda.get(x, y) == kYellow, b = bresenham.get(x, y) == kYellow;
            if (a || b) differ.set(x, y, a && b ? kGray : a ? kRed : kBlue);
        }
    beside({&dda, &bresenham, &differ}).save(out / "dda_vs_bresenham.png", 5);
    wrote(out / "dda_vs_bresenham.png");

    // One shallow line three ways: Bresenham, and the pipeline's line between the same pixel
    // centers (OpenGL's "diamond exit" rule: it leaves out the last pixel, so that lines
    // joined end to end do not draw their shared pixel twice).
    constexpr int kW = 32, kH = 8;
    Canvas ours(kW, kH), gpu(kW, kH);
    line_bresenham(2, 1, 29, 6, [&](int x, int y) { ours.set(x, y, kYellow); });
    const PixelVertex ends[] = {{{2.5f, 1.5f}}, {{29.5f, 6.5f}}};
    const std::vector<bool> covered = pipeline_coverage(kW, kH, softraster::Topology::Lines, ends);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            if (covered[size_t(y * kW + x)]) gpu.set(x, y, kGreen);
    beside({&ours, &gpu}).save(out / "bresenham_vs_pipeline.png", 8);
    wrote(out / "bresenham_vs_pipeline.png");
    return 0;
}
