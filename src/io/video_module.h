// The video encoder lives in a module of its own (libsoftraster_video.so, modules.h), opened
// the first time a video is written: Debian's FFmpeg brings about 130 shared libraries (its
// codecs, GnuTLS, X11...), whose loading took 32 ms of every start of the program
// (docs/performance.md "Start-up and model files"), for every command, including the many
// that write no video.
#pragma once
#include <cstddef>
#include <cstdint>

extern "C" {

struct SoftrasterVideo;  // an open video: FFmpeg's encoder and container

// The module's functions. Each reports failure with a one-line message in `error` (which
// names the file): open returns null, add and finish false.
struct SoftrasterVideoApi {
    // Starts writing `path` (`name`: the file as messages call it) as WebM (VP9, or VP8
    // where VP9 is missing) if `webm`, else MP4 (H.264, or MPEG-4 part 2), frames of width x
    // height (even) at fps frames per second.
    SoftrasterVideo* (*open)(const char* path, const char* name, bool webm, int width, int height, int fps, char* error, size_t error_size);
    // Encodes the next frame: width x height RGBA8 texels, row 0 at the top (alpha dropped).
    bool (*add)(SoftrasterVideo* video, const uint8_t* rgba, char* error, size_t error_size);
    // Flushes the encoder and completes the file.
    bool (*finish)(SoftrasterVideo* video, char* error, size_t error_size);
    // Frees everything (the file stays as it is).
    void (*close)(SoftrasterVideo* video);
};
using SoftrasterVideoApiFn = const SoftrasterVideoApi* (*)();
#define SOFTRASTER_VIDEO_API "softraster_video_api"
#define SOFTRASTER_VIDEO_MODULE "libsoftraster_video.so"

}
