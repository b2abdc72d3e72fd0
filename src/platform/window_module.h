// The viewer's window lives in a module of its own (libsoftraster_window.so, io/modules.h),
// opened by `softraster view`: SDL2, SDL2_ttf and X11 bring some 50 shared libraries, whose
// loading took 2 ms of every start of the program (docs/performance.md "Start-up and model
// files"), for every command, including the many that open no window. Window (window.h) is
// the program's side.
#pragma once
#include <cstddef>
#include <cstdint>

#include "platform/window.h"

extern "C" {

struct SoftrasterWindow;  // an open window: SDL's window and the status line's font

struct SoftrasterWindowApi {
    // Opens a resizable window whose drawing area is width x height, with room below it for
    // the status line; null and a one-line message in `error` where it cannot (no display).
    SoftrasterWindow* (*open)(const char* title, int width, int height, char* error, size_t error_size);
    // Shows width x height RGBA8 texels, row 0 at the top (scaled to the drawing area if the
    // sizes differ), and the status line (`error` in red instead, when not empty).
    void (*present)(SoftrasterWindow* window, const uint8_t* rgba, int width, int height, const char* status, const char* error);
    // Up to `capacity` (at least 3) input events since the last call, waiting up to wait_ms
    // for the first when there is none; returns how many. (Those past capacity wait.)
    int (*events)(SoftrasterWindow* window, int wait_ms, softraster::platform::InputEvent* out, int capacity);
    void (*close)(SoftrasterWindow* window);
};
using SoftrasterWindowApiFn = const SoftrasterWindowApi* (*)();
#define SOFTRASTER_WINDOW_API "softraster_window_api"
#define SOFTRASTER_WINDOW_MODULE "libsoftraster_window.so"

}
