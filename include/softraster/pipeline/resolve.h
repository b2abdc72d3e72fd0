// Stage 13, resolve: the multisampled buffer becomes the picture (src/pipeline/resolve.cpp).
#pragma once
#include "softraster/framebuffer.h"
#include "softraster/image.h"

namespace softraster {

class WorkerPool;

// Writes the picture of `fb` into `out` (resized to fit): each channel of a pixel is
// floor(mean + 0.5) of its samples' 8-bit values; a copy when single-sampled. In an sRGB
// framebuffer r, g, b are averaged in linear light: the decoded samples' mean, encoded.
// Framebuffer::read_pixels() is this into a new Image; reusing `out` saves allocating it.
// With a pool, its threads share the rows.
void resolve(const Framebuffer& fb, Image& out, WorkerPool* pool = nullptr);

// Supersampling's resolve: each pixel of the result is the box-filtered k x k block of `in`
// (whose size is k times the result's), each channel floor(mean + 0.5) of the block's values
// (sRGB: r, g, b averaged in linear light, as resolve does).
Image downsample_box(const Image& in, int k, ColorSpace color = ColorSpace::Linear);

// Pictures of the other buffers, one value per pixel (its first sample): the stored depth,
// and the stencil values (`clear` everywhere when the framebuffer has no stencil buffer).
GrayImage<float> depth_picture(const Framebuffer& fb);
GrayImage<uint8_t> stencil_picture(const Framebuffer& fb, uint8_t clear);
// Depth as 16-bit gray: 65535 (z - lo) / (hi - lo) rounded, lo and hi the least and greatest
// finite values (all 0 when they are equal or there are none; non-finite values give 0).
GrayImage<uint16_t> normalize_depth16(const GrayImage<float>& depth);

}  // namespace softraster
