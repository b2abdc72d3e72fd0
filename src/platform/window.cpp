#include "platform/window.h"

#include <algorithm>
#include <cstdlib>

#include <SDL.h>
#include <SDL_ttf.h>

#include "softraster/error.h"

namespace softraster::platform {

namespace {
constexpr int kStatusHeight = 22;
const char* const kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";  // Debian's fonts-dejavu-core
}  // namespace

struct Window::Impl {
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_Texture* texture = nullptr;
    int texture_w = 0, texture_h = 0;
    TTF_Font* font = nullptr;
    bool dragging[4] = {false, false, false, false};
};

Window::Window(const std::string& title, int width, int height) : impl_(std::make_unique<Impl>()) {
    // Without X11 or Wayland (an SSH session, a server) SDL would try the console's own
    // devices; say so instead, unless SDL_VIDEODRIVER asks for one.
    const bool display = std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY") || std::getenv("SDL_VIDEODRIVER");
    // The pictures are finished pixels: SDL's software renderer copies them to the window,
    // with no OpenGL (which would start a GL driver and its threads beside ours).
    SDL_SetHint(SDL_HINT_RENDER_DRIVER, "software");
    SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    if (!display || SDL_Init(SDL_INIT_VIDEO) != 0)
        throw InputError(std::string("no display to open a window on (") + (display ? SDL_GetError() : "DISPLAY is not set") +
                         "): try 'softraster view --terminal' or 'softraster animate'");
    impl_->window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height + kStatusHeight,
                                     SDL_WINDOW_RESIZABLE);
    if (!impl_->window) throw InputError(std::string("cannot open a window: ") + SDL_GetError());
    impl_->renderer = SDL_CreateRenderer(impl_->window, -1, SDL_RENDERER_SOFTWARE);
    if (!impl_->renderer) throw std::runtime_error(std::string("SDL renderer: ") + SDL_GetError());
    if (TTF_Init() == 0) impl_->font = TTF_OpenFont(kFont, 13);
}

Window::~Window() {
    if (impl_->font) TTF_CloseFont(impl_->font);
    TTF_Quit();
    if (impl_->texture) SDL_DestroyTexture(impl_->texture);
    if (impl_->renderer) SDL_DestroyRenderer(impl_->renderer);
    if (impl_->window) SDL_DestroyWindow(impl_->window);
    SDL_Quit();
}

void Window::present(const Image& frame, const std::string& status, const std::string& error) {
    Impl& w = *impl_;
    if (!w.texture || w.texture_w != frame.width || w.texture_h != frame.height) {
        if (w.texture) SDL_DestroyTexture(w.texture);
        // RGBA bytes in memory order: ABGR8888 on a little-endian machine.
        w.texture = SDL_CreateTexture(w.renderer, SDL_PIXELFORMAT_RGBA32, SDL_TEXTUREACCESS_STREAMING, frame.width, frame.height);
        w.texture_w = frame.width, w.texture_h = frame.height;
    }
    SDL_UpdateTexture(w.texture, nullptr, frame.pixels.data(), frame.width * 4);
    int win_w = 0, win_h = 0;
    SDL_GetRendererOutputSize(w.renderer, &win_w, &win_h);
    SDL_SetRenderDrawColor(w.renderer, 24, 24, 28, 255);
    SDL_RenderClear(w.renderer);
    const SDL_Rect picture{0, 0, win_w, std::max(1, win_h - kStatusHeight)};
    SDL_RenderCopy(w.renderer, w.texture, nullptr, &picture);
    const std::string& line = error.empty() ? status : error;
    if (w.font && !line.empty()) {
        const SDL_Color color = error.empty() ? SDL_Color{230, 230, 230, 255} : SDL_Color{255, 90, 80, 255};
        if (SDL_Surface* text = TTF_RenderUTF8_Blended(w.font, line.c_str(), color)) {
            if (SDL_Texture* t = SDL_CreateTextureFromSurface(w.renderer, text)) {
                const SDL_Rect at{6, win_h - kStatusHeight + (kStatusHeight - text->h) / 2, text->w, text->h};
                SDL_RenderCopy(w.renderer, t, nullptr, &at);
                SDL_DestroyTexture(t);
            }
            SDL_FreeSurface(text);
        }
    }
    SDL_RenderPresent(w.renderer);
}

std::vector<InputEvent> Window::events(int wait_ms) {
    std::vector<InputEvent> out;
    SDL_Event e;
    bool have = (wait_ms > 0 ? SDL_WaitEventTimeout(&e, wait_ms) : SDL_PollEvent(&e)) != 0;
    while (have) {
        switch (e.type) {
            case SDL_QUIT: out.push_back({InputEvent::Kind::Quit}); break;
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
                if (key) out.push_back({InputEvent::Kind::Key, key});
                break;
            }
            case SDL_MOUSEBUTTONDOWN:
            case SDL_MOUSEBUTTONUP:
                if (e.button.button < 4) impl_->dragging[e.button.button] = e.type == SDL_MOUSEBUTTONDOWN;
                break;
            case SDL_MOUSEMOTION:
                for (int b = 1; b < 4; ++b)
                    if (impl_->dragging[b]) out.push_back({InputEvent::Kind::Drag, 0, b, float(e.motion.xrel), float(e.motion.yrel)});
                break;
            case SDL_MOUSEWHEEL: out.push_back({InputEvent::Kind::Wheel, 0, 0, 0.0f, float(e.wheel.y)}); break;
            case SDL_WINDOWEVENT:
                if (e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED)
                    out.push_back({InputEvent::Kind::Resize, 0, 0, 0, 0, e.window.data1, std::max(1, e.window.data2 - kStatusHeight)});
                break;
            default: break;
        }
        have = SDL_PollEvent(&e) != 0;
    }
    return out;
}

}  // namespace softraster::platform
