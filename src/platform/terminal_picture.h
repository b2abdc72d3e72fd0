// A picture drawn in the terminal, for a quick look over SSH: 24-bit color half blocks
// (each character cell shows two pixels, its upper and lower half, as foreground and
// background colors), laid out by chafa (Debian's libchafa) to fit the terminal.
#pragma once
#include <cstdio>

#include "softraster/image.h"

namespace softraster::platform {

// The terminal's size in character cells: stdout's window size, else $COLUMNS x $LINES,
// else 80 x 24.
struct TerminalSize {
    int columns = 80, rows = 24;
};
TerminalSize terminal_size();

// Prints `picture` to `out`, as large as fits in `cells` (one row left for the prompt),
// keeping its aspect ratio (a cell twice as tall as wide), then resets the colors.
void print_terminal_picture(const Image& picture, TerminalSize cells, std::FILE* out);

}  // namespace softraster::platform
