// What commands write and say: answers on stdout, status on stderr (silenced by --quiet); solve's
// files all new or all old; a failed write (a full disk, a full stdout) as one line naming the
// target; tables that end at --to; --digits.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"
#include "support/zip_entries.hpp"

namespace fs = std::filesystem;
using dragon_test::contains;
using dragon_test::count_lines;
using dragon_test::fresh_dir;
using dragon_test::run_dragon;
using dragon_test::slurp;

namespace {

std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

// Writes beyond `kib` KiB fail with EFBIG ("File too large") instead of killing the process:
// a full disk, for one run.
std::string file_size_limit(int kib) { return "trap '' XFSZ; ulimit -f " + std::to_string(kib) + ";"; }

// The distinct times of a long-form CSV table, in order.
std::vector<std::string> times_of(const std::string& csv) {
    std::vector<std::string> out;
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        const std::string t = line.substr(0, line.find(','));
        if (out.empty() || out.back() != t) out.push_back(t);
    }
    return out;
}

}  // namespace

TEST(CliOutputs, StatusGoesToStderrAndQuietSilencesIt) {
    const fs::path dir = fresh_dir("out");
    struct Case {
        std::string args, file;
    };
    const std::vector<Case> cases = {
        {"simulate --to 2 -o " + (dir / "t.csv").string(), "t.csv"},
        {"collide --from 400 -o " + (dir / "c.json").string(), "c.json"},
        {"render --time 1 --size 64x64 -o " + (dir / "r.png").string(), "r.png"},
        {"turnaround --no-clearance -o " + (dir / "study.csv").string(), "study.csv"},
        {"figures --only plot_s_curve,fig1_link_geometry --scale 0.65 -o " + dir.string(), "plot_s_curve.png"},
        {"video --size 64x48 --fps 5 --to 1 -o " + (dir / "v.gif").string(), "v.gif"},
        {"solve --only q1 -o " + dir.string(), "result1.xlsx"},
    };
    for (const Case& c : cases) {
        const auto loud = run_dragon(c.args);
        ASSERT_EQ(loud.code, 0) << c.args << "\n" << loud.err;
        EXPECT_EQ(loud.err.rfind("wrote ", 0), 0u) << c.args << "\n" << loud.err;
        EXPECT_TRUE(contains(loud.err, c.file)) << loud.err;
        EXPECT_FALSE(contains(loud.out, "wrote")) << c.args << "\n" << loud.out;
        const auto quiet = run_dragon(c.args + " --quiet");
        ASSERT_EQ(quiet.code, 0) << c.args;
        EXPECT_EQ(quiet.err, "") << c.args;
        EXPECT_EQ(quiet.out, loud.out) << c.args;  // the answers, unchanged
    }
}

TEST(CliOutputs, SolveChecksEveryTargetFirst) {
    // An earlier run's files, and a folder where result4.xlsx goes: nothing may change.
    const fs::path dir = fresh_dir("out");
    for (const char* name : {"result1.xlsx", "result2.xlsx", "summary.json"}) std::ofstream(dir / name) << "old";
    fs::create_directory(dir / "result4.xlsx");
    const auto r = run_dragon("solve -o " + dir.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_TRUE(contains(r.err, "result4.xlsx' is a folder")) << r.err;
    EXPECT_EQ(r.out, "");  // refused before any work
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{"result1.xlsx", "result2.xlsx", "result4.xlsx", "summary.json"}));
    for (const char* name : {"result1.xlsx", "result2.xlsx", "summary.json"}) EXPECT_EQ(slurp(dir / name), "old") << name;
}

TEST(CliOutputs, SolveWritesAllOrNothingWhenAWriteFails) {
    const fs::path dir = fresh_dir("out");
    for (const char* name : {"result1.xlsx", "result4.xlsx", "summary.json"}) std::ofstream(dir / name) << "old";
    // result1.xlsx is ~1.4 MB: past 64 KiB, its write fails, after Q1's table was computed.
    const auto r = run_dragon("solve --only q1,q4 -o " + dir.string(), file_size_limit(64));
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(count_lines(r.err), 1) << r.err;  // nothing but the one line
    EXPECT_TRUE(contains(r.err, "dragon: failed: cannot write '" + (dir / "result1.xlsx").string() + "': File too large"))
        << r.err;
    EXPECT_EQ(names_in(dir), (std::vector<std::string>{"result1.xlsx", "result4.xlsx", "summary.json"}));
    for (const char* name : {"result1.xlsx", "result4.xlsx", "summary.json"}) EXPECT_EQ(slurp(dir / name), "old") << name;
}

TEST(CliOutputs, AFullStdoutFailsTheRun) {
    const fs::path dir = fresh_dir("out");
    std::ofstream(dir / "summary.json") << "old";
    const auto solve = run_dragon("solve --only q1 -o " + dir.string(), "", "/dev/full");
    EXPECT_EQ(solve.code, 1);
    EXPECT_EQ(solve.err, "dragon: failed: cannot write the answers to standard output: No space left on device\n");
    EXPECT_EQ(slurp(dir / "summary.json"), "old");  // the run failed: its files are not committed
    // Output small enough to sit in stdout's buffer until the end.
    const auto small = run_dragon("max-speed --json", "", "/dev/full");
    EXPECT_EQ(small.code, 1);
    EXPECT_EQ(count_lines(small.err), 1) << small.err;
    const auto table = run_dragon("simulate --to 3", "", "/dev/full");
    EXPECT_EQ(table.code, 1);
    EXPECT_EQ(count_lines(table.err), 1) << table.err;
}

TEST(CliOutputs, AFailedWriteNamesTheTarget) {
    const fs::path dir = fresh_dir("out");
    for (const std::string name : {"x.png", "x.svg", "x.csv", "x.xlsx", "x.mp4"}) {
        const std::string target = (dir / name).string();
        std::string args = "render --time 1 -o " + target;
        if (name == "x.csv" || name == "x.xlsx") args = "simulate --to 100 -o " + target;
        if (name == "x.mp4") args = "video --to 30 --size 640x480 -o " + target;
        const auto r = run_dragon(args, file_size_limit(8));
        EXPECT_EQ(r.code, 1) << args;
        EXPECT_EQ(r.err, "dragon: failed: cannot write '" + target + "': File too large\n") << args;
        EXPECT_TRUE(names_in(dir).empty()) << args;  // neither the target nor a temporary file
    }
    const auto figure = run_dragon("figures --only fig2_dragon_300s -o " + dir.string(), file_size_limit(8));
    EXPECT_EQ(figure.code, 1);
    EXPECT_EQ(figure.err, "dragon: failed: cannot write '" + (dir / "fig2_dragon_300s.png").string() +
                              "': File too large\n");
}

TEST(CliOutputs, WorkbooksAreTheSameBytesFromRunToRun) {
    const fs::path dir = fresh_dir("out");
    ASSERT_EQ(run_dragon("simulate --path turnaround --from -3 --to 3 -q -o " + (dir / "a.xlsx").string()).code, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // a clock-stamped workbook would differ now
    ASSERT_EQ(run_dragon("simulate --path turnaround --from -3 --to 3 -q -o " + (dir / "b.xlsx").string()).code, 0);
    EXPECT_EQ(slurp(dir / "a.xlsx"), slurp(dir / "b.xlsx"));
}

// The tool packs its workbooks at zlib's level 1 (WorkbookOptions' default): every deflated
// part says so in its header.
TEST(CliOutputs, TheToolsWorkbooksAreDeflatedFast) {
    const fs::path dir = fresh_dir("out");
    ASSERT_EQ(run_dragon("solve --only q2 -q -o " + dir.string()).code, 0);
    const auto entries = dragon_test::zip_entries(dir / "result2.xlsx");
    ASSERT_GE(entries.size(), 5u);  // [Content_Types].xml, the sheet, the workbook, styles, ...
    int deflated = 0;
    for (const auto& e : entries) {
        if (e.method != 8) continue;
        ++deflated;
        EXPECT_EQ(e.flags & 6, 6) << e.name;
    }
    EXPECT_GT(deflated, 0);
}

TEST(CliOutputs, TablesEndAtToWhenTheStepsLandOnIt) {
    // 0.1 * 3 is 0.30000000000000004 in binary: still the last time asked for.
    EXPECT_EQ(times_of(run_dragon("simulate --step 0.1 --to 0.3").out),
              (std::vector<std::string>{"0", "0.1", "0.2", "0.3"}));
    EXPECT_EQ(times_of(run_dragon("simulate --step 0.7 --to 2.1").out),
              (std::vector<std::string>{"0", "0.7", "1.4", "2.1"}));
    EXPECT_EQ(times_of(run_dragon("simulate --from 1 --step 0.25 --to 2").out),
              (std::vector<std::string>{"1", "1.25", "1.5", "1.75", "2"}));
    // 0.3 does not divide 1: the last step before --to, as --help says.
    EXPECT_EQ(times_of(run_dragon("simulate --step 0.3 --to 1").out),
              (std::vector<std::string>{"0", "0.3", "0.6", "0.9"}));
    EXPECT_TRUE(contains(run_dragon("simulate --help").out, "else at the last step before it"));
}

TEST(CliOutputs, DigitsSetTheDecimals) {
    // The head starts on turn 16 of the 0.55 m spiral: radius 8.8 m on the x axis, at 1 m/s.
    const auto three = run_dragon("simulate --to 0 --digits 3");
    ASSERT_EQ(three.code, 0) << three.err;
    EXPECT_TRUE(contains(three.out, "\n0,0,8.800,0.000,1.000\n")) << three.out.substr(0, 200);
    const auto all = run_dragon("simulate --to 0 --digits 17");
    const std::regex row(R"(\n0,0,8\.[78]\d{16},-?0\.\d{17},(1\.0{17}|0\.9{17})\n)");
    EXPECT_TRUE(std::regex_search(all.out, row)) << all.out.substr(0, 200);
    const fs::path json = dragon_test::scratch_dir() / "c.json";
    const auto hit = run_dragon("collide --from 400 -q --digits 2 -o " + json.string());
    ASSERT_EQ(hit.code, 0) << hit.err;
    const std::regex two(R"(\[-?\d+\.\d{2}, )");
    EXPECT_TRUE(std::regex_search(slurp(json), two)) << slurp(json).substr(0, 200);
}
