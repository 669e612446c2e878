// One vocabulary on the command line: a scenario file, a sweep file and a storyboard in today's
// form run silently; their old names run the same with one "dragon: warning:" line each on
// stderr (with -q too), naming the key to write; a key in both forms is refused.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;

using dragon_test::CliRun;
using dragon_test::run_dragon;

namespace {

std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dragon_test::scratch_dir() / name;
    std::ofstream(p) << text;
    return p.string();
}

// How many warning lines `err` holds.
int warnings(const std::string& err) {
    int n = 0;
    for (std::size_t at = 0; (at = err.find("dragon: warning: ", at)) != std::string::npos; ++at) ++n;
    return n;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string kToday = "bench_count = 60\nwidth = 0.28\npath = \"turnaround\"\nturn_pitch = 1.6\nspeed = 1.5\n";
const std::string kOld = "[dragon]\nbench_count = 60\nwidth = 0.28\n[path]\nkind = \"turnaround\"\nturn_pitch = 1.6\n"
                         "[motion]\nhead_speed = 1.5\n";

}  // namespace

TEST(CliVocabulary, AnOldScenarioFileRunsTheSameWithAWarningPerOldName) {
    const std::string today = write("today.toml", kToday), old = write("old.toml", kOld);
    const CliRun t = run_dragon("collide --json --scenario " + today);
    ASSERT_EQ(t.code, 0) << t.err;
    EXPECT_EQ(t.err, "");
    for (const char* quiet : {"", " -q"}) {
        const CliRun o = run_dragon("collide --json --scenario " + old + quiet);
        ASSERT_EQ(o.code, 0) << o.err;
        EXPECT_EQ(o.out, t.out);  // the same scenario, the same answer
        EXPECT_EQ(warnings(o.err), 5) << o.err;
        EXPECT_EQ(dragon_test::count_lines(o.err), 5) << o.err;
        EXPECT_TRUE(has(o.err, "dragon: warning: scenario file '" + old +
                                   "': [motion] head_speed is an old name: write speed = 1.5 at the top level\n"))
            << o.err;
        EXPECT_TRUE(has(o.err, "[path] kind is an old name: write path = \"turnaround\" at the top level")) << o.err;
        EXPECT_TRUE(has(o.err, "[dragon] bench_count is an old name: write bench_count = 60")) << o.err;
    }
}

TEST(CliVocabulary, AKeyInBothFormsIsRefusedNamingBoth) {
    const std::string both = write("both.toml", "speed = 2\n[motion]\nhead_speed = 1.5\n");
    const CliRun r = run_dragon("collide --json --scenario " + both);
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(dragon_test::count_lines(r.err), 1) << r.err;
    EXPECT_TRUE(has(r.err, "dragon: error: scenario file '" + both + "': speed and [motion] head_speed both set")) << r.err;
    EXPECT_EQ(r.out, "");
}

TEST(CliVocabulary, ASweepFilesOldNamesRunTheSameWithAWarningEach) {
    const std::string sweep_today = write("sw-today.toml", "measure = \"turnaround\"\nvary = [\"arc_ratio=1,2\"]\n"
                                                           "[fixed]\nbody_length = 2.1\n");
    const std::string sweep_old = write("sw-old.toml", "measure = \"turnaround\"\nvary = [\"arc-ratio=1,2\"]\n"
                                                       "[fixed]\nbody-length = 2.1\n");
    // One worker: the rows come out in the grid's order, so that the two runs' stdout compare.
    const CliRun t = run_dragon("sweep " + sweep_today + " -q --workers 1");
    ASSERT_EQ(t.code, 0) << t.err;
    EXPECT_EQ(t.err, "");
    const CliRun o = run_dragon("sweep " + sweep_old + " -q --workers 1");
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(o.out, t.out);
    EXPECT_EQ(warnings(o.err), 2) << o.err;
    EXPECT_EQ(dragon_test::count_lines(o.err), 2) << o.err;
    EXPECT_TRUE(has(o.err, "vary \"arc-ratio=1,2\" is an old name: write \"arc_ratio=1,2\"")) << o.err;
    EXPECT_TRUE(has(o.err, "[fixed] body-length is an old name: write body_length = 2.1")) << o.err;
    // The same axis on the command line (the flag's spelling there) still replaces the file's.
    const CliRun c = run_dragon("sweep " + sweep_today + " -q --vary arc-ratio=3");
    ASSERT_EQ(c.code, 0) << c.err;
    EXPECT_EQ(dragon_test::count_lines(c.out), 3) << c.out;  // the spec line, the header and one row
}

TEST(CliVocabulary, AStoryboardsOldScenarioFileWarnsOnce) {
    write("old-shot.toml", "[path]\npitch = 0.6\n");
    const std::string story = write("vocab-story.toml", "[film]\nsize = \"96x64\"\nfps = 5\nscenario = \"old-shot.toml\"\n"
                                                        "[[shot]]\nfrom = 10\nto = 11\nrate = 2\n"
                                                        "[[shot]]\nfrom = 11\nto = 12\nrate = 2\n");
    const std::string poster = (dragon_test::scratch_dir() / "vocab-poster.png").string();
    const CliRun r = run_dragon("film " + story + " -o " + poster + " --at 0.5 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(dragon_test::count_lines(r.err), 1) << r.err;  // two shots, one file: one warning
    EXPECT_TRUE(has(r.err, "dragon: warning: scenario file '")) << r.err;
    EXPECT_TRUE(has(r.err, "[path] pitch is an old name: write pitch = 0.6 at the top level")) << r.err;
}
