// The platform layer of `softraster view`: a window that shows finished pictures and reports
// the user's input, through SDL2 in a module opened with the first window (window_module.h;
// the pixels are only presented there; the pictures, and the double buffering of the viewer,
// are softraster's own: src/cli/view_command.cpp).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "softraster/image.h"

namespace softraster::platform {

struct InputEvent {
    enum class Kind { Quit, Key, Drag, Wheel, Resize } kind;
    int key = 0;               // Key: a lowercase letter, a digit or ' ', or one of the codes below
    int button = 0;            // Drag: 1 left, 2 middle, 3 right
    float dx = 0, dy = 0;      // Drag: pixels moved; Wheel: steps (dy > 0 away from the user)
    int width = 0, height = 0; // Resize: the new size of the drawing area
};
inline constexpr int kKeyLeft = 1000, kKeyRight = 1001, kKeyUp = 1002, kKeyDown = 1003, kKeyEscape = 1004, kKeyF12 = 1005;

class Window {
public:
    // Opens a resizable window whose drawing area is width x height, with room below it for
    // the status line. Throws InputError when there is no display to open it on, or no
    // window module.
    Window(const std::string& title, int width, int height);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // Shows `frame` (scaled to the drawing area if their sizes differ) and the status line
    // (`error` in red instead, when not empty).
    void present(const Image& frame, const std::string& status, const std::string& error);
    // The input since the last call; waits up to `wait_ms` for the first when there is none.
    std::vector<InputEvent> events(int wait_ms);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace softraster::platform
