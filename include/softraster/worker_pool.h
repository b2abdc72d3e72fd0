// A fixed set of worker threads that run parallel loops: the calling thread takes part, and
// indices are handed out one at a time from an atomic counter (dynamic scheduling), so a
// slow item does not hold up the others. Used by the front end (chunks of primitives) and
// the back end (screen tiles).
//
// A frame is a few loops in quick succession (vertices, binning, tiles; and per shadow
// map), so an idle worker first watches for the next loop for a while, and sleeps only
// after that: a sleeping thread takes tens of microseconds to wake, which each loop would
// otherwise pay at its start and, waiting for the wake-up, at its end. A loop's caller
// waits only for the workers that joined it, not for those that had not yet woken.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace softraster {

class WorkerPool {
public:
    // threads: total threads including the caller; 0 means one per core.
    explicit WorkerPool(unsigned threads = 0);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    unsigned size() const { return unsigned(workers_.size()) + 1; }

    // Calls fn(index, thread) for every index in [0, count), thread in [0, size()); returns
    // when all are done. Not reentrant.
    void parallel_for(size_t count, const std::function<void(size_t, unsigned)>& fn);

private:
    void worker_main(unsigned thread);
    void run_items(unsigned thread);
    bool wait_for_loop(uint64_t seen);  // false: the pool is stopping

    std::vector<std::thread> workers_;
    std::mutex mutex_;  // guards sleeping and waking only
    std::condition_variable wake_, done_;
    const std::function<void(size_t, unsigned)>* job_ = nullptr;
    size_t count_ = 0;
    std::atomic<size_t> next_{0};
    std::atomic<uint64_t> generation_{0};  // bumps once per loop
    std::atomic<bool> open_{false};        // a loop is running: a worker that comes may join it
    std::atomic<unsigned> joined_{0};      // workers inside the current loop
    std::atomic<bool> stop_{false};
};

}  // namespace softraster
