// The other display of `softraster view` (--terminal): the frames drawn in the terminal it
// runs in (terminal_picture.h), the keys read from it, for a look over SSH. The same two
// calls as the window (window.h), so the viewer's loop drives either.
#pragma once
#include <string>
#include <vector>

#include <termios.h>

#include "platform/terminal_picture.h"
#include "platform/window.h"
#include "softraster/image.h"

namespace softraster::platform {

class Terminal {
public:
    // Takes over the terminal: its alternate screen, keys one at a time without echo, the
    // cursor hidden. Throws InputError when stdin or stdout is not a terminal.
    Terminal();
    ~Terminal();  // gives the terminal back as it was
    Terminal(const Terminal&) = delete;
    Terminal& operator=(const Terminal&) = delete;

    // Draws `frame` as large as fits, and below it the status line (or `error`).
    void present(const Image& frame, const std::string& status, const std::string& error);
    // The keys pressed since the last call (letters, digits and space as themselves, the
    // arrows and Esc as window.h's codes), waiting up to `wait_ms` for the first; a changed
    // terminal size comes as a Resize of 0 x 0 (draw again, the frame keeps its size).
    std::vector<InputEvent> events(int wait_ms);

private:
    termios saved_{};
    TerminalSize size_;
};

}  // namespace softraster::platform
