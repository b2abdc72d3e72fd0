// libsoftraster_window.so: the viewer's window through SDL2 (see window_module.h for why
// this is a module of its own). The status line is set in DejaVu Sans through SDL2_ttf.
#include "platform/window_module.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <SDL.h>
#include <SDL_ttf.h>
#include <X11/Xlib.h>

using softraster::platform::InputEvent;

namespace {
constexpr int kStatusHeight = 22;

// Xlib's default answer to a protocol error is to end the program (exit code 1). SDL sends
// events to other windows (the root, a selection's requester) that may be gone by then: under
// Xvfb a window quit with 'q' sometimes ended with "BadWindow ... X_SendEvent" this way. Such
// an error does not concern the pictures: say it, and go on. (Set before SDL starts, so
// that SDL's own safety net passes errors on to this one.)
int report_x_error(Display* display, XErrorEvent* e) {
    char text[256] = "";
    XGetErrorText(display, e->error_code, text, sizeof text);
    std::fprintf(stderr, "softraster view: X error ignored: %s (request %d)\n", text, int(e->request_code));
    return 0;
}
const char* const kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // Debian's fonts-dejavu-core
}  // namespace

struct SoftrasterWindow {
    SDL_Window* window = nullptr;
    TTF_Font* font = nullptr;
    bool dragging[4] = {false, false, false, false};
    ~SoftrasterWindow() {
        if (font) TTF_CloseFont(font);
        TTF_Quit();
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
    }
};

namespace {

SoftrasterWindow* open(const char* title, int width, int height, char* error, size_t error_size) {
    // Without X11 or Wayland (an SSH session, a server) SDL would try the console's own
    // devices; say so instead, unless SDL_VIDEODRIVER asks for one.
    const bool display = std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY") || std::getenv("SDL_VIDEODRIVER");
    // The pictures are finished pixels, copied straight into the window's own surface, with
    // no OpenGL (which would start a GL driver and its threads beside ours).
    SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    XSetErrorHandler(report_x_error);
    if (!display || SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::snprintf(error, error_size, "no display to open a window on (%s): try 'softraster view --terminal' or 'softraster animate'",
                      display ? SDL_GetError() : "DISPLAY is not set");
        return nullptr;
    }
    auto* w = new SoftrasterWindow;
    w->window = SDL_CreateWindow(title, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height + kStatusHeight, SDL_WINDOW_RESIZABLE);
    if (!w->window) {
        std::snprintf(error, error_size, "cannot open a window: %s", SDL_GetError());
        delete w;
        return nullptr;
    }
    if (TTF_Init() == 0) w->font = TTF_OpenFont(kFont, 13);
    return w;
}

void present(SoftrasterWindow* w, const uint8_t* rgba, int width, int height, const char* status, const char* error) {
    SDL_Surface* surface = SDL_GetWindowSurface(w->window);  // (a new one after a resize)
    if (!surface) return;
    const SDL_Rect picture{0, 0, surface->w, std::max(1, surface->h - kStatusHeight)};
    const SDL_Rect bar{0, picture.h, surface->w, surface->h - picture.h};
    SDL_FillRect(surface, &bar, SDL_MapRGB(surface->format, 24, 24, 28));
    if (width == picture.w && height == picture.h && !SDL_MUSTLOCK(surface)) {
        // One pass from our RGBA bytes to the window's pixel format (the usual case).
        SDL_ConvertPixels(width, height, SDL_PIXELFORMAT_RGBA32, rgba, width * 4, surface->format->format, surface->pixels, surface->pitch);
    } else if (SDL_Surface* in = SDL_CreateRGBSurfaceWithFormatFrom(const_cast<uint8_t*>(rgba), width, height, 32, width * 4, SDL_PIXELFORMAT_RGBA32)) {
        SDL_Rect to = picture;  // the window was resized and this frame is of the old size: scaled
        SDL_BlitScaled(in, nullptr, surface, &to);
        SDL_FreeSurface(in);
    }
    const char* line = *error ? error : status;
    if (w->font && *line) {
        const SDL_Color color = *error ? SDL_Color{255, 90, 80, 255} : SDL_Color{230, 230, 230, 255};
        if (SDL_Surface* text = TTF_RenderUTF8_Blended(w->font, line, color)) {
            SDL_Rect at{6, bar.y + (kStatusHeight - text->h) / 2, text->w, text->h};
            SDL_BlitSurface(text, nullptr, surface, &at);
            SDL_FreeSurface(text);
        }
    }
    SDL_UpdateWindowSurface(w->window);
}

int events(SoftrasterWindow* w, int wait_ms, InputEvent* out, int capacity) {
    using softraster::platform::kKeyDown, softraster::platform::kKeyEscape, softraster::platform::kKeyF12, softraster::platform::kKeyLeft,
        softraster::platform::kKeyRight, softraster::platform::kKeyUp;
    int n = 0;
    auto push = [&](const InputEvent& e) { out[n++] = e; };
    SDL_Event e;
    bool have = (wait_ms > 0 ? SDL_WaitEventTimeout(&e, wait_ms) : SDL_PollEvent(&e)) != 0;
    while (have) {
        switch (e.type) {
            case SDL_QUIT: push({InputEvent::Kind::Quit}); break;
            case SDL_KEYDOWN: {
                const SDL_Keycode k = e.key.keysym.sym;
                int key = 0;
                if ((k >= 'a' && k <= 'z') || (k >= '0' && k <= '9') || k == ' ') key = int(k);
                else if (k == SDLK_LEFT) key = kKeyLeft;
                else if (k == SDLK_RIGHT) key = kKeyRight;
                else if (k == SDLK_UP) key = kKeyUp;
                else if (k == SDLK_DOWN) key = kKeyDown;
                else if (k == SDLK_ESCAPE) key = kKeyEscape;
                else if (k == SDLK_F12) key = kKeyF12;
                if (key) push({InputEvent::Kind::Key, key});
                break;
            }
            case SDL_MOUSEBUTTONDOWN:
            case SDL_MOUSEBUTTONUP:
                if (e.button.button < 4) w->dragging[e.button.button] = e.type == SDL_MOUSEBUTTONDOWN;
                break;
            case SDL_MOUSEMOTION:
                for (int b = 1; b < 4; ++b)
                    if (w->dragging[b]) push({InputEvent::Kind::Drag, 0, b, float(e.motion.xrel), float(e.motion.yrel)});
                break;
            case SDL_MOUSEWHEEL: push({InputEvent::Kind::Wheel, 0, 0, 0.0f, float(e.wheel.y)}); break;
            case SDL_WINDOWEVENT:
                if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED)
                    push({InputEvent::Kind::Resize, 0, 0, 0, 0, e.window.data1, std::max(1, e.window.data2 - kStatusHeight)});
                break;
            default: break;
        }
        have = n + 3 <= capacity && SDL_PollEvent(&e) != 0;  // (an event makes up to three)
    }
    return n;
}

const SoftrasterWindowApi kApi = {open, present, events, [](SoftrasterWindow* w) { delete w; }};

}  // namespace

extern "C" __attribute__((visibility("default"))) const SoftrasterWindowApi* softraster_window_api() { return &kApi; }
