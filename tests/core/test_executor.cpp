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

// Runs `count` items on `ex` that each wait (up to 10 s) for all of them to have started: they
// finish at once only if they all run at the same time. Returns how many had started.
int all_at_once(Executor& ex, int count) {
    std::atomic<int> arrived{0};
    ex.parallel_for(static_cast<std::size_t>(count), [&](std::size_t, int) {
        ++arrived;
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (arrived.load() < count && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
    });
    return arrived.load();
}

TEST(Executor, NestedWorkRunsOnTheOtherWorkers) {
    // One outer item starts inner work whose two items must run at the same time: the pool's
    // other thread has to take one of them (solve's Q3 inside its list of questions).
    ThreadPool pool(2);
    std::atomic<int> met{0};
    const auto start = std::chrono::steady_clock::now();
    pool.parallel_for(1, [&](std::size_t, int) { met = all_at_once(pool, 2); });
    EXPECT_EQ(met.load(), 2);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << "the inner items ran one after the other";
}

TEST(Executor, WorkerNumbersStayUniqueInNestedJobs) {
    ThreadPool pool(3);
    std::atomic<bool> shared{false};
    std::atomic<int> inner{0};
    pool.parallel_for(6, [&](std::size_t, int) {
        std::vector<std::atomic<int>> busy(3);
        pool.parallel_for(50, [&](std::size_t, int worker) {
            ASSERT_GE(worker, 0);
            ASSERT_LT(worker, 3);
            if (busy[static_cast<std::size_t>(worker)]++ != 0) shared = true;
            std::this_thread::sleep_for(std::chrono::microseconds(50));
            --busy[static_cast<std::size_t>(worker)];
            ++inner;
        });
    });
    EXPECT_EQ(inner.load(), 300);
    EXPECT_FALSE(shared.load()) << "two threads of one job ran under one worker number";
}

TEST(Executor, ConcurrentCallersDoNotQueue) {
    // Two threads start work on one pool at the same moment; each job's items wait for the
    // other job's to have started. With one job at a time this would take the 10 s give-up.
    ThreadPool pool(3);
    std::atomic<int> started{0};
    const auto wait_for_both = [&](std::size_t, int) {
        ++started;
        const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (started.load() < 2 && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
    };
    const auto start = std::chrono::steady_clock::now();
    std::thread other([&] { pool.parallel_for(1, wait_for_both); });
    pool.parallel_for(1, wait_for_both);
    other.join();
    EXPECT_EQ(started.load(), 2);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << "the second caller waited for the first";
    // And with items that need the pool's threads: jobs of several items from two callers.
    std::atomic<int> total{0};
    std::thread third([&] { pool.parallel_for(200, [&](std::size_t, int) { ++total; }); });
    pool.parallel_for(200, [&](std::size_t, int) { ++total; });
    third.join();
    EXPECT_EQ(total.load(), 400);
}

TEST(Executor, NoExecutorMeansTheCallingThread) {
    InlineExecutor serial;
    EXPECT_EQ(&executor_or(nullptr, serial), &serial);
    ThreadPool pool(2);
    EXPECT_EQ(&executor_or(&pool, serial), &pool);
    const std::thread::id me = std::this_thread::get_id();
    bool elsewhere = false;
    serial.parallel_for(3, [&](std::size_t, int) { elsewhere = elsewhere || std::this_thread::get_id() != me; });
    EXPECT_FALSE(elsewhere);
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
