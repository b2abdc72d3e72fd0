// Writing an animation frame by frame, in the format the output name says, each through a
// well-kept library (no encoder is written here):
//   .mp4   H.264 (libx264 through FFmpeg's libavcodec and libavformat; MPEG-4 part 2 where
//          that encoder is missing), 4:2:0, BT.601 limited range
//   .webm  VP9 (libvpx through FFmpeg), or VP8 where VP9 is missing
//          (FFmpeg in a module of the library's, opened with the first video: a missing
//          module is an InputError naming it)
//   .gif   giflib; each frame's 256-color palette and dithering from libimagequant; loops
//   NAME%04d.png (any printf number, any picture extension image_write.h knows): one
//          picture per frame, numbered from 0
// A video or GIF is written under a temporary name and renamed into place by finish(), so
// a failure (or an animation abandoned before finish) leaves no partial file. Errors throw
// std::runtime_error naming the file; an output name these cannot write, InputError.
#pragma once
#include <filesystem>
#include <memory>
#include <string>

#include "softraster/image.h"
#include "softraster/srgb.h"

namespace softraster {

class AnimationWriter {
public:
    virtual ~AnimationWriter() = default;
    // The next frame: width x height as opened (alpha is dropped in video and GIF).
    virtual void add(const Image& frame) = 0;
    // Completes the file (flushes the encoder, moves it into place).
    virtual void finish() = 0;
};

// Checks the output name and opens the writer for frames of width x height at `fps`
// frames per second. `color` is how the frames' values are encoded (for EXR frames).
std::unique_ptr<AnimationWriter> open_animation(const std::filesystem::path& out, int width, int height, int fps,
                                                ColorSpace color = ColorSpace::Linear);

// Throws InputError unless `out` names something open_animation can write (without
// opening it): the check before any frame is rendered.
void check_animation_path(const std::filesystem::path& out);

// Frame k's file name for a numbered pattern ("frames/%04d.png", 7 -> "frames/0007.png").
std::string numbered_frame(const std::string& pattern, int k);

}  // namespace softraster
