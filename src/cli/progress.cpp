#include "cli/progress.h"

#include <cstdio>
#include <utility>

#include <unistd.h>

namespace softraster::cli {

Progress::Progress(size_t total, std::string unit)
    : total_(total), unit_(std::move(unit)), terminal_(isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { clear(); }

void Progress::update(size_t done, const std::string& note, bool force) {
    if (!terminal_) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && shown_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const double rate = seconds > 0.0 ? double(done) / seconds : 0.0;
    constexpr int kWidth = 30;
    const int filled = total_ ? int(double(kWidth) * double(done) / double(total_)) : kWidth;
    std::string bar(size_t(filled), '#');
    bar.resize(kWidth, '.');
    char eta[32] = "--:--";
    if (rate > 0.0 && done < total_) {
        const long left = long(double(total_ - done) / rate + 0.5);
        std::snprintf(eta, sizeof eta, "%ld:%02ld", left / 60, left % 60);
    } else if (done >= total_) {
        std::snprintf(eta, sizeof eta, "0:00");
    }
    std::fprintf(stderr, "\r[%s] %zu/%zu  %.1f %s/s  ETA %s%s%s\033[K", bar.c_str(), done, total_, rate, unit_.c_str(), eta,
                 note.empty() ? "" : "  ", note.c_str());
    std::fflush(stderr);
    shown_ = true;
}

void Progress::clear() {
    if (!terminal_ || !shown_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    shown_ = false;
}

}  // namespace softraster::cli
