// A sweep survives being killed: SIGKILL in the middle, then --resume, gives exactly the rows of
// a run that was never stopped (none lost, none twice), even with a torn last row; an unfinished
// sweep is never silently overwritten, nor resumed by another. Shards merged equal the whole,
// and a merge with a part missing or given twice fails naming the scenario.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "sweep_support.hpp"

namespace fs = std::filesystem;
using dragon_test::contains;
using dragon_test::count_lines;
using dragon_test::run_dragon;
using dragon_test::slurp;

namespace {

// 30 turnaround clearance checks, about 3 s on 2 cores: long enough to be killed in the middle.
const std::string kSlow = "--vary bench-count=60:130:15 --vary arc-ratio=1.5,2 --measure turnaround --workers 2 -q";
// 12 quick scenarios for the shards.
const std::string kQuick = "--vary bench-count=20:40:6 --vary arc-ratio=1.5,2 --measure max-speed -q";

pid_t spawn_sweep(const std::string& out) {
    std::vector<std::string> args = {"sweep", "-o", out};
    std::string word;
    for (std::istringstream in(kSlow); in >> word;) args.push_back(word);
    return dragon_test::spawn_dragon(args);
}

// The rows a file holds, its first two lines aside.
std::size_t rows_in(const fs::path& p) {
    const int lines = count_lines(slurp(p));
    return lines > 2 ? static_cast<std::size_t>(lines - 2) : 0;
}

sweep_test::Table run_whole(const fs::path& out, const std::string& spec) {
    const dragon_test::CliRun r = run_dragon("sweep -o " + out.string() + " " + spec);
    EXPECT_EQ(r.code, 0) << r.err;
    return sweep_test::read_table(slurp(out));
}

}  // namespace

TEST(CliSweepResume, KilledThenResumedEqualsAnUninterruptedRun) {
    const fs::path dir = dragon_test::scratch_dir();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    const fs::path out = dir / "rows.csv", partial = dir / "rows.csv.partial";
    const pid_t pid = spawn_sweep(out.string());
    ASSERT_GT(pid, 0);
    // Killed once a few rows are durable, well before all 30 are.
    using namespace std::chrono;
    const auto limit = steady_clock::now() + seconds(120);
    while (steady_clock::now() < limit && (!fs::exists(partial) || rows_in(partial) < 4))
        std::this_thread::sleep_for(milliseconds(5));
    ::kill(pid, SIGKILL);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before the kill";
    ASSERT_FALSE(fs::exists(out));  // only a finished sweep has its name
    const std::size_t before = rows_in(partial);
    EXPECT_GE(before, 4u);
    EXPECT_LT(before, 30u);
    // What a kill in the middle of a write would leave: a row cut short, without its line end.
    std::ofstream(partial, std::ios::app | std::ios::binary) << "95,2,3.0054176677890347,1.50270";

    // Without --resume the unfinished rows are not thrown away.
    dragon_test::CliRun r = run_dragon("sweep -o " + out.string() + " " + kSlow);
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(contains(r.err, "--resume")) << r.err;
    // Nor gone on with by another sweep.
    r = run_dragon("sweep --resume -o " + out.string() + " --vary bench-count=60:130:15 --vary arc-ratio=1.5,2.5 "
                   "--measure turnaround -q");
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(contains(r.err, "another sweep")) << r.err;

    r = run_dragon("sweep --resume -o " + out.string() + " " + kSlow);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(fs::exists(partial));
    const sweep_test::Table resumed = sweep_test::read_table(slurp(out));
    const sweep_test::Table whole = run_whole(dir / "whole.csv", kSlow);
    ASSERT_EQ(whole.rows.size(), 30u);
    EXPECT_EQ(resumed.spec, whole.spec);
    EXPECT_EQ(resumed.header, whole.header);
    EXPECT_EQ(sweep_test::row_set(resumed), sweep_test::row_set(whole));  // as multisets: none lost, none twice

    // Resuming a finished sweep computes nothing and keeps its rows.
    r = run_dragon("sweep --resume -o " + out.string() + " " + kSlow.substr(0, kSlow.size() - 3));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(contains(r.err, "30 of 30 rows")) << r.err;
    EXPECT_EQ(sweep_test::row_set(sweep_test::read_table(slurp(out))), sweep_test::row_set(whole));
}

TEST(CliSweepShards, MergedEqualTheWholeAndMustHoldEachScenarioOnce) {
    const fs::path dir = dragon_test::scratch_dir();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    const sweep_test::Table whole = run_whole(dir / "whole.csv", kQuick);
    ASSERT_EQ(whole.rows.size(), 12u);
    std::string parts;
    std::size_t rows = 0;
    for (int k = 1; k <= 3; ++k) {
        const fs::path part = dir / ("part" + std::to_string(k) + ".csv");
        const sweep_test::Table t = run_whole(part, kQuick + " --shard " + std::to_string(k) + "/3");
        EXPECT_EQ(t.rows.size(), 4u);
        EXPECT_TRUE(contains(t.spec, "\"shard\":\"" + std::to_string(k) + "/3\"")) << t.spec;
        rows += t.rows.size();
        parts += " " + part.string();
    }
    EXPECT_EQ(rows, whole.rows.size());
    const fs::path merged = dir / "merged.csv";
    dragon_test::CliRun r = run_dragon("sweep merge " + merged.string() + parts + " --plot " + (dir / "map.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "map.png"));
    const sweep_test::Table m = sweep_test::read_table(slurp(merged));
    EXPECT_EQ(m.spec, whole.spec);
    EXPECT_EQ(m.header, whole.header);
    EXPECT_EQ(sweep_test::row_set(m), sweep_test::row_set(whole));

    fs::remove(merged);
    r = run_dragon("sweep merge " + merged.string() + " " + (dir / "part1.csv").string() + " " +
                   (dir / "part3.csv").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(count_lines(r.err), 1);
    EXPECT_TRUE(contains(r.err, "4 of the sweep's 12 scenarios are missing, the first: bench-count=20 arc-ratio=2"))
        << r.err;
    EXPECT_FALSE(fs::exists(merged));
    r = run_dragon("sweep merge " + merged.string() + parts + " " + (dir / "part2.csv").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(contains(r.err, "twice")) << r.err;
    EXPECT_TRUE(contains(r.err, "part2.csv")) << r.err;
    EXPECT_FALSE(fs::exists(merged));
    // A part whose run was killed (its last row torn): resume it before merging.
    fs::copy_file(dir / "part2.csv", dir / "torn.csv");
    std::ofstream(dir / "torn.csv", std::ios::app | std::ios::binary) << "40,2,1.2";
    r = run_dragon("sweep merge " + merged.string() + " " + (dir / "part1.csv").string() + " " +
                   (dir / "torn.csv").string() + " " + (dir / "part3.csv").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(contains(r.err, "torn")) << r.err;
    EXPECT_FALSE(fs::exists(merged));
    // A part of another sweep.
    run_whole(dir / "other.csv", "--vary bench-count=20:40:6 --vary arc-ratio=1.5,2 --measure max-speed --limit 1.9 -q");
    r = run_dragon("sweep merge " + merged.string() + parts + " " + (dir / "other.csv").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(contains(r.err, "other.csv")) << r.err;
    EXPECT_FALSE(fs::exists(merged));
}

// A row whose measure failed (for a reason not the scenario's: the run exits 1 and its rows stay
// unfinished) is made again by --resume, and the finished file holds the good row in its place.
TEST(CliSweepResume, FailedRowsAreMadeAgain) {
    const fs::path dir = dragon_test::scratch_dir();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    const std::string spec = "--vary bench-count=20:40:3 --measure max-speed -q";
    const sweep_test::Table whole = run_whole(dir / "whole.csv", spec);
    ASSERT_EQ(whole.rows.size(), 3u);
    // The second row as a failed measure writes it: its cells empty, its status saying so.
    const std::vector<std::string> lines = sweep_test::lines(slurp(dir / "whole.csv"));
    std::string failed = sweep_test::fields(lines[3])[0];
    for (std::size_t k = 1; k + 1 < whole.header.size(); ++k) failed += ",";
    failed += ",failed (max-speed): the search did not converge";
    std::ofstream(dir / "rows.csv.partial") << lines[0] << "\n" << lines[1] << "\n" << lines[2] << "\n" << failed << "\n";
    const dragon_test::CliRun r = run_dragon("sweep --resume -o " + (dir / "rows.csv").string() + " " +
                                             spec.substr(0, spec.size() - 3));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(contains(r.err, "resuming: 1 failed row of")) << r.err;
    EXPECT_TRUE(contains(r.err, "1 of 3 rows is in")) << r.err;
    EXPECT_EQ(sweep_test::row_set(sweep_test::read_table(slurp(dir / "rows.csv"))), sweep_test::row_set(whole));
    EXPECT_FALSE(fs::exists(dir / "rows.csv.partial"));
}
