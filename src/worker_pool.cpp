#include "softraster/worker_pool.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>

namespace softraster {
namespace {

// How long an idle worker watches for the next loop before it sleeps, and how long a loop's
// caller watches for its workers to finish before it sleeps (see worker_pool.h).
constexpr auto kWatch = std::chrono::microseconds(200);

uint64_t pack(uint64_t begin, uint64_t end) { return begin << 32 | end; }
uint64_t begin_of(uint64_t run) { return run >> 32; }
uint64_t end_of(uint64_t run) { return run & 0xffffffffu; }

// Claims the first indices of a share, [first, last), up to `grain` of them (its owner's
// claim); false if it has none left.
bool claim(std::atomic<uint64_t>& share, uint64_t grain, size_t& first, size_t& last) {
    uint64_t run = share.load(std::memory_order_relaxed);
    for (;;) {
        const uint64_t b = begin_of(run), e = end_of(run);
        if (b >= e) return false;
        const uint64_t to = b + std::min(grain, e - b);  // (not b + grain: any grain is allowed)
        if (share.compare_exchange_weak(run, pack(to, e), std::memory_order_relaxed)) {
            first = size_t(b), last = size_t(to);
            return true;
        }
    }
}

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// Returns once done(): spins for up to kWatch, then sleeps on `cv` (whoever makes done()
// true takes `mutex` before notifying, so the wake-up is not lost).
template <class F>
void watch_then_sleep(std::mutex& mutex, std::condition_variable& cv, F&& done) {
    if (done()) return;
    const auto until = std::chrono::steady_clock::now() + kWatch;
    for (int k = 0;; ++k) {
        for (int i = 0; i < 64; ++i) {
            if (done()) return;
            cpu_relax();
        }
        if ((k & 15) == 15 && std::chrono::steady_clock::now() > until) break;
    }
    std::unique_lock lock(mutex);
    cv.wait(lock, done);
}

}  // namespace

WorkerPool::WorkerPool(unsigned threads) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    shares_ = std::make_unique<Share[]>(threads);
    for (unsigned t = 1; t < threads; ++t) workers_.emplace_back([this, t] { worker_main(t); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& w : workers_) w.join();
}

void WorkerPool::run_items(unsigned thread) {
    const Job job = job_;
    const uint64_t grain = grain_;
    size_t i, first, last;
    for (;;) {
        while (claim(shares_[thread].run, grain, first, last))
            for (i = first; i < last; ++i) job.call(job.data, i, thread);
        if (!steal(thread, i)) return;
        job.call(job.data, i, thread);
    }
}

bool WorkerPool::steal(unsigned thief, size_t& index) {
    // Half of what is left, not one index: a thief and an owner claiming one index each from
    // the same share moved its cache line between their cores at every item (some 200 ns
    // each way), which with a thousand small draws in a loop cost more than the draws
    // (docs/performance.md). With half, the thief then claims from its own share.
    for (;;) {
        Share* fullest = nullptr;
        uint64_t most = 0, run = 0;
        for (unsigned t = 0; t < size(); ++t) {
            const uint64_t r = shares_[t].run.load(std::memory_order_relaxed);
            const uint64_t left = end_of(r) - begin_of(r);  // (claims keep begin <= end)
            if (left > most) fullest = &shares_[t], most = left, run = r;
        }
        // (None left: every index is claimed, or is in the share of a thief that has yet to
        // store it, and that thief claims it itself.)
        if (!fullest) return false;
        const uint64_t b = begin_of(run), e = end_of(run);  // (as scanned; the swap fails if it has changed)
        const uint64_t first = e - (e - b + 1) / 2;  // (the back half, rounded up: at least one)
        if (!fullest->run.compare_exchange_weak(run, pack(b, first), std::memory_order_relaxed)) continue;
        index = size_t(first);
        // (The thief's own share is empty, so no one else claims from it before this.)
        shares_[thief].run.store(pack(first + 1, e), std::memory_order_relaxed);
        return true;
    }
}

bool WorkerPool::wait_for_loop(uint64_t seen) {
    watch_then_sleep(mutex_, wake_, [&] { return stop_.load() || generation_.load() != seen; });
    return !stop_.load();
}

void WorkerPool::worker_main(unsigned thread) {
    uint64_t seen = 0;
    while (wait_for_loop(seen)) {
        seen = generation_.load();
        // Join, unless the loop has already ended (its caller did every item before this
        // worker came). Joining first and looking second: the caller closes the loop, then
        // waits until no one has joined, so it either waits for this worker or this worker
        // sees the loop closed.
        joined_.fetch_add(1);
        if (open_.load()) run_items(thread);
        if (joined_.fetch_sub(1) == 1) {
            { std::lock_guard lock(mutex_); }  // (the caller is either before its check or asleep)
            done_.notify_one();
        }
    }
}

void WorkerPool::run(size_t count, Job job, std::span<const uint32_t> shares, size_t grain) {
    const uint64_t n = size();
    if (!shares.empty() && (shares.size() != n + 1 || shares[0] != 0 || shares[n] != count || !std::is_sorted(shares.begin(), shares.end())))
        throw std::invalid_argument("WorkerPool::parallel_for: shares are not size() + 1 bounds from 0 to count");
    if (grain == 0) throw std::invalid_argument("WorkerPool::parallel_for: a grain of 0 indices");
    if (count == 0) return;
    if (workers_.empty() || count == 1) {
        for (size_t i = 0; i < count; ++i) job.call(job.data, i, 0);
        return;
    }
    if (count > std::numeric_limits<uint32_t>::max()) throw std::length_error("WorkerPool::parallel_for: 2^32 items or more");
    job_ = job;
    grain_ = grain;
    for (uint64_t t = 0; t < n; ++t) {
        const uint64_t begin = shares.empty() ? count * t / n : shares[t], end = shares.empty() ? count * (t + 1) / n : shares[t + 1];
        shares_[t].run.store(pack(begin, end), std::memory_order_relaxed);
    }
    open_.store(true);  // (a worker that sees the loop open sees its shares)
    {
        std::lock_guard lock(mutex_);  // (a worker going to sleep sees the new generation or is woken)
        generation_.fetch_add(1);
    }
    wake_.notify_all();
    run_items(0);
    open_.store(false);
    watch_then_sleep(mutex_, done_, [&] { return joined_.load() == 0; });
    job_ = {};
}

}  // namespace softraster
