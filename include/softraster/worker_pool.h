// A fixed set of worker threads that run parallel loops: the calling thread takes part.
// Each thread starts on a share of its own, a contiguous run of the indices, and takes them
// in order; a thread whose share is done takes the back half of the fullest share left as
// its own (work stealing), so a slow item does not hold up the others. Neighbouring items
// thus run on one core one after another: the back end's screen tiles side by side, whose
// framebuffer rows and texels lie next to each other in memory, and the front end's chunks
// of a mesh. Handing out indices one at a time from one shared counter interleaved the
// threads' tiles instead (docs/performance.md, "Tiles in shares").
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
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "softraster/cache_line_allocator.h"

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
    // when all are done. count is below 2^32. Not reentrant. Thread t starts on indices
    // [shares[t], shares[t + 1]) when `shares` is given (size() + 1 bounds, from 0 to count,
    // not decreasing), else on an equal run.
    //
    // Every thread reads the loop's function at every index, so it is copied onto cache lines
    // of its own first. Passed as a std::function made on the caller's stack, it shared a line
    // with what the calling thread writes while it runs its own items, and each of a worker's
    // reads fetched that line back from the caller's core: a thousand small draws lost some
    // 10% at 2 threads (docs/performance.md, "The loop's function on a line of its own").
    // What the function refers to is read at every index as well: a loop of small items
    // should hold copies (capture by value), not references to the caller's locals, whose
    // lines the same writes may share (Context::execute_batch's loops lost 7% to 10% so).
    //
    // A thread claims up to `grain` indices of its share at a time (at least 1; std::invalid_argument
    // for 0), a thief still only unclaimed ones. A claim is a locked compare-and-swap, which
    // waits until every store before it has reached the cache: after an item that ends with
    // stores to lines not in the cache (a small draw's vertices and bins), each claim waits
    // out their misses, which one thread alone overlaps with the next item (a thousand small
    // draws a loop lost some 10% of the frame at 2 threads: docs/performance.md, "A claim per
    // small draw"). A larger grain is for loops of many short items; it leaves the last
    // items of a share fewer to steal.
    template <class F>
    void parallel_for(size_t count, F&& fn, std::span<const uint32_t> shares = {}, size_t grain = 1) {
        struct alignas(kCacheLine) Isolated {
            std::remove_cvref_t<F> fn;
        } const job{std::forward<F>(fn)};
        run(count, Job{&job, [](const void* j, size_t i, unsigned t) { static_cast<const Isolated*>(j)->fn(i, t); }}, shares, grain);
    }

private:
    struct Job {  // a loop's function, type-erased
        const void* data;
        void (*call)(const void* data, size_t index, unsigned thread);
    };
    void run(size_t count, Job job, std::span<const uint32_t> shares, size_t grain);
    void worker_main(unsigned thread);
    void run_items(unsigned thread);
    bool steal(unsigned thief, size_t& index);  // the back half of the fullest share; false: all are done
    bool wait_for_loop(uint64_t seen);  // false: the pool is stopping

    std::vector<std::thread> workers_;
    std::mutex mutex_;  // guards sleeping and waking only
    std::condition_variable wake_, done_;
    Job job_{};  // the current loop's (run_items reads it and grain_ once)
    uint64_t grain_ = 1;
    // A thread's share of the current loop, the indices [begin, end) packed as begin << 32 |
    // end, so that its owner (an index from the front) and thieves (half from the back) claim
    // with one compare-and-swap. One cache line each: the owner claims at every grain.
    struct alignas(kCacheLine) Share {
        std::atomic<uint64_t> run{0};
    };
    std::unique_ptr<Share[]> shares_;
    std::atomic<uint64_t> generation_{0};  // bumps once per loop
    std::atomic<bool> open_{false};        // a loop is running: a worker that comes may join it
    std::atomic<unsigned> joined_{0};      // workers inside the current loop
    std::atomic<bool> stop_{false};
};

// Calls fn(index, thread) for every index in [0, count): on the pool's threads
// (WorkerPool::parallel_for, with its `shares` and `grain`), or with no pool in order on the
// calling thread, as thread 0 (the shares and the grain then say nothing).
template <class F>
void parallel_for(WorkerPool* pool, size_t count, F&& fn, std::span<const uint32_t> shares = {}, size_t grain = 1) {
    if (pool) return pool->parallel_for(count, std::forward<F>(fn), shares, grain);
    for (size_t i = 0; i < count; ++i) fn(i, 0u);
}

}  // namespace softraster
