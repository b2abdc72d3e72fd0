// A fixed set of worker threads that run parallel loops: the calling thread takes part, and
// indices are handed out one at a time from an atomic counter (dynamic scheduling), so a
// slow item does not hold up the others. Used by the front end (chunks of primitives) and
// the back end (screen tiles).
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

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    const std::function<void(size_t, unsigned)>* job_ = nullptr;
    size_t count_ = 0;
    std::atomic<size_t> next_{0};
    unsigned busy_ = 0;         // workers still in the current job
    uint64_t generation_ = 0;   // bumps once per job
    bool stop_ = false;
};

}  // namespace softraster
