#include "platform/terminal_picture.h"

#include <algorithm>
#include <cstdlib>

#include <chafa.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace softraster::platform {

TerminalSize terminal_size() {
    TerminalSize size;
    winsize w{};
    if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 0 && w.ws_row > 0) return {w.ws_col, w.ws_row};
    const char* columns = std::getenv("COLUMNS");
    const char* lines = std::getenv("LINES");
    if (columns && std::atoi(columns) > 0) size.columns = std::atoi(columns);
    if (lines && std::atoi(lines) > 0) size.rows = std::atoi(lines);
    return size;
}

void print_terminal_picture(const Image& picture, TerminalSize cells, std::FILE* out) {
    gint columns = std::max(1, cells.columns), rows = std::max(1, cells.rows - 1);
    chafa_calc_canvas_geometry(picture.width, picture.height, &columns, &rows, 0.5f, TRUE, FALSE);
    ChafaSymbolMap* symbols = chafa_symbol_map_new();
    chafa_symbol_map_add_by_tags(symbols, ChafaSymbolTags(CHAFA_SYMBOL_TAG_VHALF | CHAFA_SYMBOL_TAG_SPACE | CHAFA_SYMBOL_TAG_SOLID));
    ChafaCanvasConfig* config = chafa_canvas_config_new();
    chafa_canvas_config_set_geometry(config, columns, rows);
    chafa_canvas_config_set_canvas_mode(config, CHAFA_CANVAS_MODE_TRUECOLOR);
    chafa_canvas_config_set_pixel_mode(config, CHAFA_PIXEL_MODE_SYMBOLS);
    chafa_canvas_config_set_symbol_map(config, symbols);
    ChafaCanvas* canvas = chafa_canvas_new(config);
    chafa_canvas_draw_all_pixels(canvas, CHAFA_PIXEL_RGBA8_UNASSOCIATED, reinterpret_cast<const guint8*>(picture.pixels.data()),
                                 picture.width, picture.height, picture.width * 4);
    // The terminal database's fallback: the standard sequences for 24-bit color, whatever
    // $TERM says (the picture is asked for; a terminal without them shows escapes).
    ChafaTermInfo* info = chafa_term_db_get_fallback_info(chafa_term_db_get_default());
    GString* text = chafa_canvas_print(canvas, info);
    std::fwrite(text->str, 1, text->len, out);
    std::fputs("\033[0m\n", out);
    std::fflush(out);
    g_string_free(text, TRUE);
    chafa_term_info_unref(info);
    chafa_canvas_unref(canvas);
    chafa_canvas_config_unref(config);
    chafa_symbol_map_unref(symbols);
}

}  // namespace softraster::platform
