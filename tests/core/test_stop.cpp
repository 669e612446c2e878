// A caller can stop the library's long computations (a host's Ctrl-C): they throw Cancelled
// soon after the request, from any thread, and leave nothing half done.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "dragon/analyses.hpp"
#include "dragon/contest.hpp"
#include "dragon/executor.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;
using Clock = std::chrono::steady_clock;

namespace {

// Runs `work` on `stoppable`, asks it to stop after `delay`, and returns how long the work went
// on after that before it threw Cancelled (or -1 s if it finished or threw anything else).
// The bound the tests hold it to is the host's: a Ctrl-C answered within half a second.
template <class Work>
double seconds_to_stop(StoppableExecutor& stoppable, Work&& work, std::chrono::milliseconds delay) {
    Clock::time_point asked{};
    std::thread stopper([&] {
        std::this_thread::sleep_for(delay);
        asked = Clock::now();
        stoppable.request_stop();
    });
    double after = -1.0;
    try {
        work();
    } catch (const Cancelled&) {
        after = std::chrono::duration<double>(Clock::now() - asked).count();
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
    }
    stopper.join();
    return after;
}

}  // namespace

TEST(Stop, AStoppedExecutorStartsNoItem) {
    InlineExecutor inner;
    StoppableExecutor ex(inner);
    int ran = 0;
    ex.parallel_for(3, [&](std::size_t, int) { ++ran; });
    EXPECT_EQ(ran, 3);
    ex.request_stop();
    EXPECT_THROW(ex.parallel_for(3, [&](std::size_t, int) { ++ran; }), Cancelled);
    EXPECT_EQ(ran, 3);
    // Work nested inline inside it stops too.
    InlineExecutor nested(&ex);
    EXPECT_THROW(nested.parallel_for(1, [&](std::size_t, int) { ++ran; }), Cancelled);
}

TEST(Stop, LongComputationsStopSoonAfterTheRequest) {
    ThreadPool pool(2);
    // A minimum pitch on a fine grid (seconds of work), the contest's questions, a long
    // speed-ratio scan: each stops within half a second of the request (and does stop).
    const auto stopped_soon = [](double after) { return after >= 0.0 && after < 0.5; };
    {
        StoppableExecutor ex(pool);
        MinPitchOptions o;
        o.grid = 1e-5;
        o.executor = &ex;
        EXPECT_TRUE(stopped_soon(seconds_to_stop(ex, [&] { min_pitch(Scenario{}, 0.35, 0.55, o); },
                                                 std::chrono::milliseconds(200))));
    }
    {
        StoppableExecutor ex(pool);
        ContestOptions o;
        o.pitch_grid = 1e-5;
        o.executor = &ex;
        EXPECT_TRUE(stopped_soon(seconds_to_stop(ex, [&] { solve_contest(Scenario{}, o); }, std::chrono::milliseconds(200))));
    }
    {
        StoppableExecutor ex(pool);
        Scenario s;
        s.path.kind = PathKind::turnaround;
        s.bench.bench_count = 1000;
        const RunWindow wide{Along::metres(-1000.0), Along::metres(1000.0)};
        EXPECT_TRUE(stopped_soon(seconds_to_stop(ex, [&] { max_head_speed(s, 2.0, wide, &ex); },
                                                 std::chrono::milliseconds(200))));
    }
}
