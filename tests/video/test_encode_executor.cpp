// encode_frames on the caller's executor: it draws on that executor's workers and no others,
// makes the same film on any of them (one worker, several, or from inside another job), and a
// paint error on any stops them all and leaves no file.
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "support/scratch.hpp"

#include "dragon/executor.hpp"
#include "dragon/video.hpp"
#include "video/synthetic.hpp"

namespace fs = std::filesystem;
using namespace dragon;

namespace {

std::string scratch(const std::string& name) {
    const fs::path p = dragon_test::scratch_dir() / name;
    fs::remove(p);
    return p.string();
}

std::string bytes_of(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// An executor that runs on a pool of its own and counts the jobs it was given.
class CountingPool final : public Executor {
public:
    explicit CountingPool(int workers) : pool_(workers) {}
    int workers() const override { return pool_.workers(); }
    void parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& body) override {
        ++jobs;
        pool_.parallel_for(count, body);
    }
    std::atomic<int> jobs{0};

private:
    ThreadPool pool_;
};

VideoOptions small(Executor* executor) {
    VideoOptions opt;
    opt.width = 64;
    opt.height = 48;
    opt.fps = 10;
    opt.executor = executor;
    return opt;
}

// 24 frames, 4 of them held; the threads that painted, and the progress seen, in order.
struct Painted {
    std::set<std::thread::id> painters;
    int last_done = 0;
    bool in_order = true;
};

void encode(const std::string& path, const VideoOptions& opt, Painted& run) {
    std::mutex m;
    const auto paint = [&](int i, cairo_t* cr) {
        {
            const std::lock_guard<std::mutex> hold(m);
            run.painters.insert(std::this_thread::get_id());
        }
        test::paint_synthetic(i, cr, opt.width, opt.height);
    };
    const EncodeStats stats = encode_frames(
        path, opt, 24, paint,
        [&](const Progress& p) {
            run.in_order = run.in_order && p.done == run.last_done + 1;
            run.last_done = p.done;
        },
        20);
    EXPECT_EQ(stats.frames, 24);
}

TEST(EncodeExecutor, OneWorkerDrawsAndEncodesOnTheCallersThread) {
    InlineExecutor one;
    Painted run;
    const std::string path = scratch("inline.gif");
    encode(path, small(&one), run);
    EXPECT_EQ(run.painters, std::set<std::thread::id>{std::this_thread::get_id()});
    EXPECT_TRUE(run.in_order);
    EXPECT_EQ(run.last_done, 24);
    ASSERT_TRUE(fs::exists(path));
}

TEST(EncodeExecutor, DrawsOnTheCallersWorkersOnly) {
    CountingPool pool(3);
    Painted run;
    const std::string path = scratch("pool.gif");
    encode(path, small(&pool), run);
    EXPECT_EQ(pool.jobs.load(), 1);
    EXPECT_LE(run.painters.size(), 3u);  // its 3 workers (the caller is one of them)
    EXPECT_TRUE(run.in_order);
    EXPECT_EQ(run.last_done, 24);
    // The same film whichever workers drew it: frames handed over in order.
    InlineExecutor one;
    Painted again;
    const std::string single = scratch("single.gif");
    encode(single, small(&one), again);
    EXPECT_EQ(bytes_of(path), bytes_of(single));
}

// From inside another job on the same pool, its parallel_for runs inline: one worker draws and
// encodes in turn, rather than waiting for workers that are busy with the outer job.
TEST(EncodeExecutor, WorksFromInsideAJobOfItsExecutor) {
    CountingPool pool(2);
    std::atomic<int> films{0};
    pool.parallel_for(2, [&](std::size_t k, int) {
        Painted run;
        encode(scratch("nested" + std::to_string(k) + ".mp4"), small(&pool), run);
        films += run.last_done == 24 && run.in_order;
    });
    EXPECT_EQ(films.load(), 2);
}

// Large frames are drawn by fewer workers, so that the frames held stay within
// kMaxFrameRingBytes: at 4096x4096 (64 MiB a frame, two a worker) two draw at once, however
// many workers the executor has.
TEST(EncodeExecutor, LargeFramesAreDrawnByFewerWorkers) {
    CountingPool pool(8);
    VideoOptions opt = small(&pool);
    opt.width = opt.height = 4096;
    std::atomic<int> drawing{0}, most{0};
    const auto paint = [&](int, cairo_t* cr) {
        const int now = ++drawing;
        for (int seen = most.load(); now > seen && !most.compare_exchange_weak(seen, now);) {
        }
        cairo_set_source_rgb(cr, 0.2, 0.4, 0.6);
        cairo_paint(cr);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));  // long enough to overlap
        --drawing;
    };
    const long frame = 4L * opt.width * opt.height;
    EXPECT_EQ(kMaxFrameRingBytes / (2 * frame), 2);
    encode_frames(scratch("large.gif"), opt, 6, paint);
    EXPECT_GE(most.load(), 1);
    EXPECT_LE(most.load(), 2);
}

TEST(EncodeExecutor, PaintErrorOnAnyWorkerLeavesNothing) {
    InlineExecutor one;
    CountingPool pool(3);
    for (Executor* e : {static_cast<Executor*>(&one), static_cast<Executor*>(&pool)}) {
        const VideoOptions opt = small(e);
        const std::string path = scratch("paint-error.mp4");
        const auto paint = [&](int i, cairo_t* cr) {
            if (i == 13) throw std::runtime_error("boom");
            test::paint_synthetic(i, cr, opt.width, opt.height);
        };
        EXPECT_THROW(encode_frames(path, opt, 40, paint), std::runtime_error);
        EXPECT_FALSE(fs::exists(path));
        int temps = 0;
        for (const auto& entry : fs::directory_iterator(fs::path(path).parent_path()))
            temps += entry.path().filename().string().rfind(".paint-error.tmp", 0) == 0;
        EXPECT_EQ(temps, 0);
    }
}

TEST(EncodeExecutor, AStopRequestEndsTheFilmWithinAFrameAndLeavesNothing) {
    // As Python's Ctrl-C does: the caller asks the executor to stop while the film is encoded.
    InlineExecutor one;
    CountingPool pool(3);
    for (Executor* inner : {static_cast<Executor*>(&one), static_cast<Executor*>(&pool)}) {
        StoppableExecutor stoppable(*inner);
        const VideoOptions opt = small(&stoppable);
        const std::string path = scratch("stopped.mp4");
        int encoded = 0;
        const auto paint = [&](int i, cairo_t* cr) { test::paint_synthetic(i, cr, opt.width, opt.height); };
        const auto progress = [&](const Progress& p) {
            encoded = p.done;
            if (p.done == 7) stoppable.request_stop();
        };
        EXPECT_THROW(encode_frames(path, opt, 400, paint, progress), Cancelled);
        EXPECT_EQ(encoded, 7);
        EXPECT_FALSE(fs::exists(path));
    }
}

}  // namespace
