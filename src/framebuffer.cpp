// The framebuffer's deferred clears (framebuffer.h): writing a tile's recorded values.
#include "softraster/framebuffer.h"

#include <cstring>

namespace softraster {

void Framebuffer::fill_tile(const Rect& r, const Rgba8* color, float depth, const uint8_t* stencil) {
    const size_t n = size_t(r.x1 - r.x0) * size_t(samples_);
    static_assert(sizeof(Rgba8) == sizeof(uint32_t));
    uint32_t word = 0;  // filled as 32-bit words, which vectorizes (four bytes do not)
    if (color) std::memcpy(&word, color, sizeof word);
    // The tile's rows are far apart in memory, out of reach of the hardware prefetcher: ask
    // for the rows a few ahead, or each row's writes wait for memory one after another.
    constexpr int kAhead = 4;
    for (int y = r.y0; y < r.y1; ++y) {
        if (y + kAhead < r.y1) {
            const auto* c = reinterpret_cast<const char*>(color_.data() + sample_index(r.x0, y + kAhead));
            const auto* d = reinterpret_cast<const char*>(depth_.data() + sample_index(r.x0, y + kAhead));
            for (size_t k = 0; k < n * sizeof(float); k += 64) {
                if (color) __builtin_prefetch(c + k, /*write=*/1);
                __builtin_prefetch(d + k, /*write=*/1);
            }
        }
        std::fill_n(depth_.data() + sample_index(r.x0, y), n, depth);
        if (color) std::fill_n(reinterpret_cast<uint32_t*>(color_.data() + sample_index(r.x0, y)), n, word);
        if (stencil && has_stencil()) std::fill_n(stencil_.data() + sample_index(r.x0, y), n, *stencil);
    }
}

}  // namespace softraster
