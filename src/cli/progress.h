// Progress of a long batch on stderr: on a terminal, one line redrawn in place (a bar,
// done/total, rate, time left); otherwise nothing here (the caller prints a plain line per item).
#pragma once
#include <chrono>
#include <cstddef>
#include <string>

namespace softraster::cli {

class Progress {
public:
    // `unit`: what is counted, for the rate ("files" -> "12.5 files/s").
    explicit Progress(size_t total, std::string unit = "files");
    ~Progress();
    bool on_terminal() const { return terminal_; }
    // `done` of total finished, `note` (e.g. "3 failed") after the numbers. Redraws at most
    // ten times a second unless `force`.
    void update(size_t done, const std::string& note, bool force = false);
    // Erases the bar so a plain line can be printed; the next update redraws it.
    void clear();

private:
    size_t total_;
    std::string unit_;
    bool terminal_;
    bool shown_ = false;
    std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace softraster::cli
