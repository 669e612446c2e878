// The executor the library's parallel work runs on: every item exactly once, worker numbers in
// range and never shared by two items at once, exceptions brought back to the caller, nested
// calls, and the analyses' answers the same on any executor.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "dragon/analyses.hpp"
#include "dragon/executor.hpp"

using namespace dragon;

TEST(Executor, EveryItemOnceOnAWorkerOfItsOwn) {
    ThreadPool pool(3);
    EXPECT_EQ(pool.workers(), 3);
    for (std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
        std::vector<std::atomic<int>> seen(count);
        std::vector<std::atomic<int>> busy(3);
        std::atomic<bool> shared{false};
        std::set<std::thread::id> threads;
        std::mutex lock;
        pool.parallel_for(count, [&](std::size_t i, int worker) {
            ASSERT_GE(worker, 0);
            ASSERT_LT(worker, 3);
            if (busy[static_cast<std::size_t>(worker)]++ != 0) shared = true;  // a worker's scratch is its own
            ++seen[i];
            {
                const std::lock_guard<std::mutex> hold(lock);
                threads.insert(std::this_thread::get_id());
            }
            --busy[static_cast<std::size_t>(worker)];
        });
        for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(seen[i].load(), 1) << "item " << i << " of " << count;
        EXPECT_FALSE(shared.load());
        EXPECT_LE(threads.size(), 3u);
    }
}

TEST(Executor, ItemsRunAtOnceOnSeveralThreads) {
    // Two items that each wait for the other can only finish if they run at the same time.
    ThreadPool pool(2);
    std::atomic<int> arrived{0};
    pool.parallel_for(2, [&](std::size_t, int) {
        ++arrived;
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (arrived.load() < 2 && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
    });
    EXPECT_EQ(arrived.load(), 2);
}

TEST(Executor, TheFirstExceptionComesBackToTheCaller) {
    ThreadPool pool(2);
    EXPECT_THROW(pool.parallel_for(100, [](std::size_t i, int) {
        if (i == 37) throw std::runtime_error("item 37");
    }), std::runtime_error);
    // The pool is still usable afterwards.
    std::atomic<int> n{0};
    pool.parallel_for(10, [&](std::size_t, int) { ++n; });
    EXPECT_EQ(n.load(), 10);
    InlineExecutor inline_executor;
    EXPECT_THROW(inline_executor.parallel_for(3, [](std::size_t, int) { throw std::logic_error("x"); }), std::logic_error);
}

TEST(Executor, NestedCallsRunInline) {
    ThreadPool pool(2);
    std::atomic<int> inner{0};
    pool.parallel_for(4, [&](std::size_t, int) {
        pool.parallel_for(5, [&](std::size_t, int worker) {
            EXPECT_EQ(worker, 0);  // inline: the one worker
            ++inner;
        });
    });
    EXPECT_EQ(inner.load(), 20);
}

TEST(Executor, TheDefaultHasAFixedSize) {
    Executor& a = default_executor();
    Executor& b = default_executor();
    EXPECT_EQ(&a, &b);
    EXPECT_GE(a.workers(), 1);
    EXPECT_THROW(set_default_workers(a.workers() + 1), std::logic_error);
    EXPECT_NO_THROW(set_default_workers(a.workers()));
    EXPECT_THROW(set_default_workers(0), std::invalid_argument);
}

TEST(Executor, AnswersDoNotDependOnTheExecutor) {
    const Simulation sim(Scenario{});
    InlineExecutor one;
    ThreadPool two(2), five(5);
    const std::vector<Frame> a = simulate_table(sim, 0.0, 300.0, 1.0, &one);
    for (Executor* ex : std::initializer_list<Executor*>{&two, &five}) {
        const std::vector<Frame> b = simulate_table(sim, 0.0, 300.0, 1.0, ex);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t k = 0; k < a.size(); ++k)
            for (std::size_t i = 0; i < a[k].handles.size(); ++i) {
                ASSERT_EQ(a[k].handles[i].pos.x(), b[k].handles[i].pos.x());
                ASSERT_EQ(a[k].handles[i].speed, b[k].handles[i].speed);
            }
    }
    MinPitchOptions serial, parallel;
    serial.executor = &one;
    parallel.executor = &five;
    const MinPitch p1 = min_pitch(Scenario{}, 0.44, 0.46, serial), p5 = min_pitch(Scenario{}, 0.44, 0.46, parallel);
    EXPECT_EQ(p1.pitch, p5.pitch);
    EXPECT_EQ(p1.intervals.size(), p5.intervals.size());
}
