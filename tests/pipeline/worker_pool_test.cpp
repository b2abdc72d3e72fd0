// The worker pool (worker_pool.h): every index of a loop runs exactly once, on a thread
// index below size(), and parallel_for returns only when all have finished, whether the
// workers were watching for the loop or asleep, and for loops of fewer items than threads.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <span>
#include <thread>
#include <vector>

#include "softraster/worker_pool.h"

using namespace softraster;

namespace {

// Runs a loop of `count` items, each taking about `work`; checks each index ran once, on a
// valid thread, and finished before parallel_for returned.
void expect_loop_runs_each_item_once(WorkerPool& pool, size_t count, std::chrono::microseconds work) {
    std::vector<std::atomic<int>> runs(count);
    std::atomic<size_t> finished{0};
    std::atomic<bool> bad_thread{false};
    pool.parallel_for(count, [&](size_t i, unsigned thread) {
        if (thread >= pool.size()) bad_thread = true;
        const auto until = std::chrono::steady_clock::now() + work;
        while (std::chrono::steady_clock::now() < until) {
        }
        runs[i].fetch_add(1);
        finished.fetch_add(1);
    });
    EXPECT_EQ(finished.load(), count);  // (not one still running)
    EXPECT_FALSE(bad_thread.load());
    for (size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i].load(), 1) << "item " << i << " of " << count;
}

// The share property: thread t's first items are its share [begin, end) from the front,
// in order, until the share is empty; every other item of the share, whoever ran it, a
// thief took from its back, so it comes after all of those.
void expect_share_taken_from_the_front(const std::vector<std::vector<size_t>>& order, unsigned t, size_t begin, size_t end) {
    size_t next = begin;  // past the owner's run from the front
    for (size_t i : order[t]) {
        if (i != next || i >= end) break;
        ++next;
    }
    for (unsigned thread = 0; thread < order.size(); ++thread)
        for (size_t k = thread == t ? next - begin : 0; k < order[thread].size(); ++k) {
            const size_t i = order[thread][k];
            if (i >= begin && i < end) {
                EXPECT_GE(i, next) << "thread " << thread << " took item " << i << " of thread " << t << "'s share from its front";
            }
        }
}

// Runs a loop of `count` items, each sleeping `work`, and returns the items each thread ran,
// in its order.
std::vector<std::vector<size_t>> order_of_loop(WorkerPool& pool, size_t count, std::chrono::microseconds work,
                                               std::span<const uint32_t> shares = {}) {
    std::vector<std::vector<size_t>> order(pool.size());  // each thread writes only its own
    pool.parallel_for(count, [&](size_t i, unsigned thread) {
        order[thread].push_back(i);
        std::this_thread::sleep_for(work);
    }, shares);
    return order;
}

}  // namespace

TEST(WorkerPool, LoopsBackToBackRunEachItemOnce) {
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        WorkerPool pool(threads);
        EXPECT_EQ(pool.size(), threads);
        for (int loop = 0; loop < 200; ++loop)  // the workers still watching for the next loop
            expect_loop_runs_each_item_once(pool, size_t(loop % 7), std::chrono::microseconds(loop % 3 == 0 ? 50 : 0));
    }
}

TEST(WorkerPool, LoopsAfterTheWorkersSleptRunEachItemOnce) {
    WorkerPool pool(3);
    for (int loop = 0; loop < 12; ++loop) {
        std::this_thread::sleep_for(std::chrono::milliseconds(3));  // long enough for the workers to sleep
        expect_loop_runs_each_item_once(pool, loop % 2 ? 2 : 40, std::chrono::microseconds(100));
    }
}

TEST(WorkerPool, EveryThreadTakesPartInALongLoop) {
    WorkerPool pool(2);
    std::atomic<int> on_worker{0};
    pool.parallel_for(64, [&](size_t, unsigned thread) {
        if (thread == 1) on_worker.fetch_add(1);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    });
    EXPECT_GT(on_worker.load(), 0);  // 64 ms of items: the worker woke and took some
}

// Each thread starts on a contiguous share of the loop, in order (the caller on the first
// count / size() items), and takes others' items only from their back: so the items a
// thread runs of its own share are the share's first ones, in order, and every item a
// thief took from that share comes after them.
TEST(WorkerPool, EachThreadRunsItsOwnShareFromTheFront) {
    for (unsigned threads : {2u, 3u}) {
        WorkerPool pool(threads);
        constexpr size_t kCount = 48;
        for (int loop = 0; loop < 3; ++loop) {  // the workers awake after the first
            const auto order = order_of_loop(pool, kCount, std::chrono::microseconds(300));
            for (unsigned t = 0; t < threads; ++t) expect_share_taken_from_the_front(order, t, kCount * t / threads, kCount * (t + 1) / threads);
        }
    }
}

// A thread whose share is done takes the back half of the fullest share left, as its own,
// from its front: with the caller's share all 80 items and the worker's none, the worker's
// first item is in the back half and its next ones follow it in order. (One index at a
// time from the back, the worker ran 79, 78, 77...; two cores claiming from one share moved
// its cache line at every item.) A millisecond an item: a worker woken up to some 70 ms late
// still finds three or more to take.
TEST(WorkerPool, AThiefTakesTheBackHalfAndRunsItInOrder) {
    WorkerPool pool(2);
    constexpr size_t kCount = 80;
    const std::vector<uint32_t> shares = {0, kCount, kCount};
    for (int loop = 0; loop < 3; ++loop) {
        const auto order = order_of_loop(pool, kCount, std::chrono::milliseconds(1), shares);
        expect_share_taken_from_the_front(order, 0, 0, kCount);
        ASSERT_GE(order[1].size(), 3u) << "the worker took fewer than three items in 80 ms";
        const size_t first = order[1][0];
        EXPECT_GE(first, kCount / 2) << "not from the back half";
        EXPECT_EQ(order[1][1], first + 1);
        EXPECT_EQ(order[1][2], first + 2);
    }
}

// Given shares, thread t starts on [shares[t], shares[t + 1]) instead of an equal run, the
// same way: its own items from the front, in order, others only from the back. Shares that
// are not size() + 1 bounds from 0 to the count are refused.
TEST(WorkerPool, GivenSharesEachThreadStartsOnItsOwn) {
    WorkerPool pool(2);
    constexpr size_t kCount = 40;
    const std::vector<uint32_t> shares = {0, 30, 40};  // the caller 30, the worker 10
    for (int loop = 0; loop < 3; ++loop) {
        const auto order = order_of_loop(pool, kCount, std::chrono::milliseconds(1), shares);
        for (unsigned t = 0; t < 2; ++t) expect_share_taken_from_the_front(order, t, shares[t], shares[t + 1]);
        EXPECT_EQ(order[0].size() + order[1].size(), kCount);
        ASSERT_FALSE(order[0].empty());
        EXPECT_EQ(order[0].front(), 0u);
        if (!order[1].empty()) {
            EXPECT_EQ(order[1].front(), 30u);  // (the caller could take 30 only after some 39 ms)
        }
    }
    auto nothing = [](size_t, unsigned) {};
    for (const std::vector<uint32_t>& bad : {std::vector<uint32_t>{0, 40}, std::vector<uint32_t>{0, 20, 39}, std::vector<uint32_t>{1, 20, 40},
                                             std::vector<uint32_t>{0, 30, 20, 40}, std::vector<uint32_t>{0, 30, 20}})
        EXPECT_THROW(pool.parallel_for(kCount, nothing, bad), std::invalid_argument);
}

// With a grain, a thread claims that many items of its share at once, and a thief takes
// only unclaimed ones. The caller's share is all 24 items, claimed 4 at a time, and its
// first item waits until the worker has run every item it could take: the caller then has
// run exactly its first claim, 0 to 3, and the worker the other 20. (Claimed one at a time,
// the worker takes 1 to 23 and the caller runs 0 only.) The worker's first item waits for the
// caller's: the worker may steal the back half before the caller's first claim, but not more
// (with the caller's thread descheduled right after it opened the loop, as on a machine busy
// with the rest of the suite, the worker could take more, and the test failed once so).
// A grain of 0 is refused.
TEST(WorkerPool, AThreadClaimsItsGrainAtATime) {
    WorkerPool pool(2);
    constexpr size_t kCount = 24, kGrain = 4;
    const std::vector<uint32_t> shares = {0, kCount, kCount};
    for (int loop = 0; loop < 3; ++loop) {
        std::vector<std::vector<size_t>> order(2);  // each thread writes only its own
        std::atomic<size_t> by_worker{0};
        std::atomic<bool> timed_out{false}, caller_started{false};
        pool.parallel_for(kCount, [&](size_t i, unsigned thread) {
            order[thread].push_back(i);
            const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
            if (thread == 1) {
                while (!caller_started.load())
                    if (std::chrono::steady_clock::now() > until) {
                        timed_out = true;
                        return;
                    }
                by_worker.fetch_add(1);
            }
            if (thread != 0 || i != 0) return;
            caller_started = true;
            while (by_worker.load() < kCount - kGrain) {
                if (std::chrono::steady_clock::now() > until) {
                    timed_out = true;
                    return;
                }
                std::this_thread::sleep_for(std::chrono::microseconds(100));
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));  // (room for a worker that takes more)
        }, shares, kGrain);
        EXPECT_FALSE(timed_out.load()) << "the worker ran " << by_worker.load() << " items in 20 s";
        EXPECT_EQ(order[0], (std::vector<size_t>{0, 1, 2, 3}));
        EXPECT_EQ(order[1].size(), kCount - kGrain);
    }
    std::vector<std::atomic<int>> runs(kCount);  // (a grain past every count: each index still once)
    pool.parallel_for(kCount, [&](size_t i, unsigned) { runs[i].fetch_add(1); }, {}, std::numeric_limits<size_t>::max());
    for (size_t i = 0; i < kCount; ++i) EXPECT_EQ(runs[i].load(), 1) << "item " << i << " with the largest grain";
    EXPECT_THROW(pool.parallel_for(kCount, [](size_t, unsigned) {}, shares, 0), std::invalid_argument);
    EXPECT_THROW(parallel_for(&pool, kCount, [](size_t, unsigned) {}, {}, 0), std::invalid_argument);  // (the free loop passes it on)
}

// Every thread reads the loop's function at every index: it is a copy of the caller's, on
// cache lines that hold nothing else (64-byte aligned, whole lines), not the caller's object,
// whose lines the caller's stack may share (worker_pool.h).
TEST(WorkerPool, TheLoopsFunctionIsACopyOnLinesOfItsOwn) {
    struct Probe {
        std::atomic<const void*>* seen;  // where each call's function lay
        std::atomic<bool>* same_everywhere;
        void operator()(size_t, unsigned) const {
            const void* expected = nullptr;
            if (!seen->compare_exchange_strong(expected, this) && expected != this) *same_everywhere = false;
        }
    };
    static_assert(sizeof(Probe) < 64);
    WorkerPool pool(2);
    std::atomic<const void*> seen{nullptr};
    std::atomic<bool> same_everywhere{true};
    const Probe probe{&seen, &same_everywhere};
    pool.parallel_for(64, probe);
    ASSERT_NE(seen.load(), nullptr);
    EXPECT_NE(seen.load(), static_cast<const void*>(&probe));
    EXPECT_EQ(reinterpret_cast<uintptr_t>(seen.load()) % 64, 0u);
    EXPECT_TRUE(same_everywhere.load());  // (one copy, read by every thread)
}

// parallel_for(pool, ...): without a pool, every index in order on the calling thread as
// thread 0; with one, the pool's loop, shares and all.
TEST(WorkerPool, TheFreeLoopRunsInlineWithoutAPool) {
    std::vector<size_t> order;
    bool other_thread = false;
    const std::thread::id caller = std::this_thread::get_id();
    parallel_for(nullptr, 5, [&](size_t i, unsigned thread) {
        order.push_back(i);
        if (thread != 0 || std::this_thread::get_id() != caller) other_thread = true;
    });
    EXPECT_EQ(order, (std::vector<size_t>{0, 1, 2, 3, 4}));
    EXPECT_FALSE(other_thread);
}

TEST(WorkerPool, TheFreeLoopWithAPoolIsThePoolsLoop) {
    WorkerPool pool(2);
    std::vector<std::atomic<int>> runs(40);
    const std::vector<uint32_t> shares = {0, 30, 40};
    parallel_for(&pool, runs.size(), [&](size_t i, unsigned) { runs[i].fetch_add(1); }, shares);
    for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << "item " << i;
    const std::vector<uint32_t> bad = {0, 20, 39};  // (the pool checks the shares it is given)
    EXPECT_THROW(parallel_for(&pool, runs.size(), [](size_t, unsigned) {}, bad), std::invalid_argument);
}
