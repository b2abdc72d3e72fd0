#include "softraster/worker_pool.h"

#include <algorithm>
#include <chrono>

namespace softraster {
namespace {

// How long an idle worker watches for the next loop before it sleeps, and how long a loop's
// caller watches for its workers to finish before it sleeps (see worker_pool.h).
constexpr auto kWatch = std::chrono::microseconds(200);

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
    for (size_t i = next_.fetch_add(1, std::memory_order_relaxed); i < count_; i = next_.fetch_add(1, std::memory_order_relaxed))
        (*job_)(i, thread);
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

void WorkerPool::parallel_for(size_t count, const std::function<void(size_t, unsigned)>& fn) {
    if (count == 0) return;
    if (workers_.empty() || count == 1) {
        for (size_t i = 0; i < count; ++i) fn(i, 0);
        return;
    }
    job_ = &fn;
    count_ = count;
    next_.store(0, std::memory_order_relaxed);
    open_.store(true);
    {
        std::lock_guard lock(mutex_);  // (a worker going to sleep sees the new generation or is woken)
        generation_.fetch_add(1);
    }
    wake_.notify_all();
    run_items(0);
    open_.store(false);
    watch_then_sleep(mutex_, done_, [&] { return joined_.load() == 0; });
    job_ = nullptr;
}

}  // namespace softraster
