#include "platform/window.h"

#include "io/modules.h"
#include "platform/window_module.h"
#include "softraster/error.h"

namespace softraster::platform {

// The module's functions, found the first time a window opens (window_module.h).
struct Window::Impl {
    const SoftrasterWindowApi& api;
    SoftrasterWindow* window;
};

Window::Window(const std::string& title, int width, int height) {
    const SoftrasterWindowApi& api = *reinterpret_cast<SoftrasterWindowApiFn>(required_module_entry(
        SOFTRASTER_WINDOW_MODULE, SOFTRASTER_WINDOW_API, "a window needs softraster's window module", ", or try 'softraster view --terminal'"))();
    char error[512] = "";
    SoftrasterWindow* window = api.open(title.c_str(), width, height, error, sizeof error);
    if (!window) throw InputError(error);
    impl_ = std::make_unique<Impl>(Impl{api, window});
}

Window::~Window() { impl_->api.close(impl_->window); }

void Window::present(const Image& frame, const std::string& status, const std::string& error) {
    impl_->api.present(impl_->window, reinterpret_cast<const uint8_t*>(frame.pixels.data()), frame.width, frame.height, status.c_str(), error.c_str());
}

std::vector<InputEvent> Window::events(int wait_ms) {
    InputEvent got[64];
    const int n = impl_->api.events(impl_->window, wait_ms, got, 64);
    return {got, got + n};
}

}  // namespace softraster::platform
