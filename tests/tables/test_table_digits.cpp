// --digits for CSV and JSON tables, and workbooks that are the same bytes from run to run.
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dragon/analyses.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/tables.hpp"
#include "support/scratch.hpp"

using namespace dragon;
namespace fs = std::filesystem;

namespace {

std::string bytes(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

}  // namespace

TEST(TableDigits, FixedDecimals) {
    EXPECT_EQ(format_fixed(1.5, 0), "2");             // half away from zero, as round6
    EXPECT_EQ(format_fixed(-2.5, 0), "-3");
    // 0.1234565 is a hair below the half in binary, but times 1e6 it rounds to 123456.5 exactly:
    // the rule is round6's (the scaled value to the nearest integer, halves away from zero).
    EXPECT_EQ(format_fixed(0.1234565, 6), "0.123457");
    EXPECT_EQ(format_fixed(-1e-9, 6), "0.000000");    // no negative zero
    EXPECT_EQ(format_fixed(-1e-20, 17), "0.00000000000000000");
    // 8.8 is 8.800000000000000710542735760100185871124267578125 in binary: 17 decimals show it.
    EXPECT_EQ(format_fixed(8.8, 17), "8.80000000000000071");
    EXPECT_EQ(format_fixed(-6.2377223503, 3), "-6.238");
    // The default agrees with round6, which the workbooks hold.
    for (double v : {0.0000005, -3.9360085, 12.3456785, 1e-7, -0.4999995})
        EXPECT_EQ(format_fixed(v, 6), fmt::format("{:.6f}", round6(v))) << v;
}

TEST(TableDigits, CsvAndJsonTakeDigits) {
    const Simulation sim(Scenario{});
    const std::vector<Frame> frames = simulate_table(sim, 0.0, 2.0, 1.0);
    const fs::path csv = dragon_test::scratch_dir() / "t.csv", json = dragon_test::scratch_dir() / "t.json";
    write_csv(frames, csv.string(), 3);
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    ASSERT_EQ(line, "t,handle,x,y,speed");
    std::getline(in, line);
    // The head starts on turn 16 of the 0.55 m spiral: at radius 8.8 m on the x axis, at 1 m/s.
    EXPECT_EQ(line, "0,0,8.800,0.000,1.000");
    write_json(frames, json.string(), 0);
    EXPECT_NE(bytes(json).find("\"x\": [9, "), std::string::npos);
    EXPECT_THROW(write_csv(frames, csv.string(), 18), InputError);
    EXPECT_THROW(write_json(frames, json.string(), -1), InputError);
}

// The time is a number of the table too: `digits` decimals, its trailing zeros dropped (so a
// grid's times read as typed), never "-0".
TEST(TableDigits, TheTimeTakesDigitsToo) {
    EXPECT_EQ(format_time(300.0, 6), "300");
    EXPECT_EQ(format_time(0.30000000000000004, 6), "0.3");
    EXPECT_EQ(format_time(0.30000000000000004, 17), "0.30000000000000004");
    EXPECT_EQ(format_time(412.4738376821459, 9), "412.473837682");
    EXPECT_EQ(format_time(412.4738376821459, 3), "412.474");
    EXPECT_EQ(format_time(-1e-9, 6), "0");
    EXPECT_EQ(format_time(2.5, 0), "3");
    // In the files: the contact time at 1e-12 s, to 12 decimals.
    const Simulation sim(Scenario{});
    Frame at = sim.frame(412.473837682146);
    const fs::path csv = dragon_test::scratch_dir() / "t.csv", json = dragon_test::scratch_dir() / "t.json";
    write_csv({at}, csv.string(), 12);
    EXPECT_NE(bytes(csv).find("\n412.473837682146,0,"), std::string::npos) << bytes(csv).substr(0, 80);
    write_json({at}, json.string(), 2);
    EXPECT_NE(bytes(json).find("{\"t\": 412.47, "), std::string::npos) << bytes(json).substr(0, 80);
}

TEST(Workbooks, SameBytesFromRunToRun) {
    const Simulation sim(Scenario{});
    const std::vector<Frame> frames = simulate_table(sim, 0.0, 3.0, 1.0);
    const fs::path a = dragon_test::scratch_dir() / "a.xlsx", b = dragon_test::scratch_dir() / "b.xlsx";
    const fs::path c = dragon_test::scratch_dir() / "c.xlsx", d = dragon_test::scratch_dir() / "d.xlsx";
    write_result_xlsx(frames, a.string());
    write_result2_xlsx(frames.back(), c.string());
    // A creation time taken from the clock would have one-second resolution: a second later,
    // a workbook stamped with the clock would differ.
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    write_result_xlsx(frames, b.string());
    write_result2_xlsx(frames.back(), d.string());
    EXPECT_EQ(bytes(a), bytes(b));
    EXPECT_EQ(bytes(c), bytes(d));
    EXPECT_GT(bytes(a).size(), 1000u);
}

// dragon solve writes its workbooks on several threads at once: each comes out byte for byte as
// written alone (at the default level, 1, named here), and stderr is never touched.
TEST(Workbooks, SeveralAtOnceOnThreads) {
    const Simulation sim(Scenario{});
    const std::vector<Frame> frames = simulate_table(sim, 0.0, 20.0, 1.0);
    const fs::path alone = dragon_test::scratch_dir() / "alone.xlsx";
    write_result_xlsx(frames, alone.string());
    std::vector<fs::path> paths;
    for (int k = 0; k < 4; ++k) paths.push_back(dragon_test::scratch_dir() / fmt::format("thread{}.xlsx", k));
    std::vector<std::thread> writers;
    for (const fs::path& p : paths)
        writers.emplace_back([&frames, p] { write_result_xlsx(frames, p.string(), WorkbookOptions{1}); });
    for (std::thread& w : writers) w.join();
    for (const fs::path& p : paths) EXPECT_EQ(bytes(p), bytes(alone)) << p;
    // File descriptor 2 is stderr again, not /dev/null.
    EXPECT_NE(fs::read_symlink("/proc/self/fd/2").string(), "/dev/null");
}

// Unless asked, a workbook leaves the process's stderr alone, even while it closes: a library
// embedded in another program (a notebook's kernel) must not touch its file descriptors.
TEST(Workbooks, StderrIsTouchedOnlyWhenAsked) {
    const Simulation sim(Scenario{});
    const std::vector<Frame> frames = simulate_table(sim, 0.0, 3.0, 1.0);
    const std::string before = fs::read_symlink("/proc/self/fd/2").string();
    std::atomic<bool> done{false}, muted{false};
    std::thread watch([&] {
        while (!done) muted = muted || fs::read_symlink("/proc/self/fd/2").string() == "/dev/null";
    });
    for (int k = 0; k < 20; ++k) write_result_xlsx(frames, (dragon_test::scratch_dir() / "w.xlsx").string());
    done = true;
    watch.join();
    EXPECT_FALSE(muted);
    EXPECT_EQ(fs::read_symlink("/proc/self/fd/2").string(), before);
}

TEST(Workbooks, IntoAnAtomicFileTheCallerCommits) {
    const Simulation sim(Scenario{});
    const fs::path target = dragon_test::scratch_dir() / "r2.xlsx";
    fs::remove(target);
    {
        AtomicFile out(target.string());
        write_result2_xlsx(sim.frame(1.0), out);
        EXPECT_FALSE(fs::exists(target));  // nothing at the target until the commit
        out.commit();
    }
    EXPECT_GT(fs::file_size(target), 1000u);
}
