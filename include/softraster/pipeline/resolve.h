// Stage 10, resolve: the multisampled buffer becomes the picture (src/pipeline/resolve.cpp).
#pragma once
#include "softraster/framebuffer.h"
#include "softraster/image.h"

namespace softraster {

// Writes the picture of `fb` into `out` (resized to fit): each channel of a pixel is
// floor(mean + 0.5) of its samples' 8-bit values; a copy when single-sampled.
// Framebuffer::read_pixels() is this into a new Image; reusing `out` saves allocating it.
void resolve(const Framebuffer& fb, Image& out);

}  // namespace softraster
