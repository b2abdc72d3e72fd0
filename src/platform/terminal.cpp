#include "platform/terminal.h"

#include <cstdio>

#include <poll.h>
#include <unistd.h>

#include "softraster/error.h"

namespace softraster::platform {

Terminal::Terminal() : size_(terminal_size()) {
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO) || tcgetattr(STDIN_FILENO, &saved_) != 0)
        throw InputError("view --terminal: stdin and stdout must be a terminal (for a picture in a pipe: render --terminal)");
    termios raw = saved_;
    raw.c_lflag &= ~tcflag_t(ICANON | ECHO);  // each key as it is pressed, not shown
    raw.c_cc[VMIN] = 0;
    raw.c_cc[VTIME] = 0;
    tcsetattr(STDIN_FILENO, TCSANOW, &raw);
    std::fputs("\033[?1049h\033[?25l", stdout);  // the alternate screen; the cursor hidden
    std::fflush(stdout);
}

Terminal::~Terminal() {
    std::fputs("\033[0m\033[?25h\033[?1049l", stdout);
    std::fflush(stdout);
    tcsetattr(STDIN_FILENO, TCSANOW, &saved_);
}

void Terminal::present(const Image& frame, const std::string& status, const std::string& error) {
    size_ = terminal_size();
    std::fputs("\033[H", stdout);  // from the top-left corner, over the last frame
    print_terminal_picture(frame, size_, stdout);
    const std::string line = error.empty() ? status : error;
    std::fprintf(stdout, "%s%.*s\033[0m\033[J", error.empty() ? "" : "\033[31m", size_.columns, line.c_str());
    std::fflush(stdout);
}

std::vector<InputEvent> Terminal::events(int wait_ms) {
    std::vector<InputEvent> out;
    pollfd in{STDIN_FILENO, POLLIN, 0};
    if (poll(&in, 1, wait_ms) > 0) {
        unsigned char bytes[64];
        const ssize_t n = read(STDIN_FILENO, bytes, sizeof bytes);
        for (ssize_t i = 0; i < n; ++i) {
            const unsigned char c = bytes[i];
            int key = 0;
            if (c == 27 && i + 2 < n && (bytes[i + 1] == '[' || bytes[i + 1] == 'O')) {  // an arrow: ESC [ A..D
                const unsigned char code = bytes[i + 2];
                key = code == 'A' ? kKeyUp : code == 'B' ? kKeyDown : code == 'C' ? kKeyRight : code == 'D' ? kKeyLeft : 0;
                i += 2;
            } else if (c == 27) {
                key = kKeyEscape;
            } else if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == ' ') {
                key = c;
            }
            if (key != 0) out.push_back({InputEvent::Kind::Key, key});
        }
    }
    const TerminalSize now = terminal_size();
    if (now.columns != size_.columns || now.rows != size_.rows) out.push_back({InputEvent::Kind::Resize});
    return out;
}

}  // namespace softraster::platform
