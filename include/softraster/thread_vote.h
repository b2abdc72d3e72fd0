// The thread that holds most of a draw's tiles, ties to the lowest, tallied a tile at a
// time: Context's choice of the thread that runs a small draw's front end the next time
// (context.h, Recorded::thread). One tally per thread, each marked with the draw it counts
// for, so that a new draw starts afresh without clearing them all.
#pragma once
#include <cstdint>
#include <vector>

namespace softraster {

class ThreadVote {
public:
    explicit ThreadVote(unsigned threads) : tally_(threads) {}

    // The next draw's vote begins.
    void start() {
        ++draw_;
        most_ = 0;
        winner_ = 0;
    }
    // One of the draw's tiles is `thread`'s.
    void add(unsigned thread) {
        Tally& t = tally_[thread];
        if (t.draw != draw_) t = {draw_, 0};
        ++t.votes;
        if (t.votes > most_ || (t.votes == most_ && thread < winner_)) most_ = t.votes, winner_ = thread;
    }
    unsigned winner() const { return winner_; }  // (0 with no tile added)

private:
    struct Tally {
        uint64_t draw = 0;
        uint32_t votes = 0;
    };
    std::vector<Tally> tally_;
    uint64_t draw_ = 0;
    uint32_t most_ = 0;
    unsigned winner_ = 0;
};

}  // namespace softraster
