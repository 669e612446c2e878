// Each command takes exactly the flags it uses; a value it never reads cannot make it fail; the
// command line names unknown commands and options with what was meant.
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/command_line.hpp"
#include "support/cli_run.hpp"

namespace fs = std::filesystem;
using dragon_test::contains;
using dragon_test::count_lines;
using dragon_test::run_dragon;

namespace {

// The scenario flags by what they set: the benches and the head speed, the plain spiral, the
// turning space, the turnaround path's own.
const std::vector<std::string> kBench = {"--bench-count", "--head-length", "--body-length", "--width",
                                         "--hole-offset", "--speed"};
const std::vector<std::string> kSpiral = {"--pitch", "--start-turn"};
const std::vector<std::string> kTurnaround = {"--turn-pitch", "--arc-ratio"};

struct Taken {
    bool path, spiral, start_turn, turn_radius, turnaround, quiet, digits;
};

// The table docs/usage.md gives: which command reads what (and every command takes --quiet).
const std::map<std::string, Taken> kTable = {
    //              --path spiral start-turn turn-radius turnaround --quiet --digits
    {"simulate", {true, true, true, true, true, true, true}},
    {"collide", {true, true, true, true, true, true, true}},
    {"render", {true, true, true, true, true, true, false}},
    {"video", {true, true, true, true, true, true, false}},
    {"solve", {false, true, true, true, true, true, false}},
    {"figures", {false, true, true, true, true, true, false}},
    {"min-pitch", {false, false, true, true, false, true, false}},
    {"turnaround", {false, false, false, true, true, true, false}},
    {"max-speed", {false, false, false, true, true, true, false}},
};

// Help lists an option as "  --pitch FLOAT ..." or "  -q,--quiet ...".
bool lists(const std::string& help, const std::string& flag) {
    return contains(help, " " + flag + " ") || contains(help, "," + flag + " ");
}

std::string toml(const std::string& name, const std::string& text) {
    const fs::path p = dragon_test::scratch_dir() / name;
    std::ofstream(p) << text;
    return p.string();
}

}  // namespace

TEST(CliFlags, EachCommandTakesTheFlagsOfWhatItReads) {
    for (const auto& [cmd, t] : kTable) {
        const auto r = run_dragon(cmd + " --help");
        ASSERT_EQ(r.code, 0) << cmd;
        EXPECT_TRUE(lists(r.out, "--scenario")) << cmd;
        for (const std::string& f : kBench) EXPECT_TRUE(lists(r.out, f)) << cmd << " " << f;
        EXPECT_EQ(lists(r.out, "--path"), t.path) << cmd;
        EXPECT_EQ(lists(r.out, "--pitch"), t.spiral) << cmd;
        EXPECT_EQ(lists(r.out, "--start-turn"), t.start_turn) << cmd;
        EXPECT_EQ(lists(r.out, "--turn-radius"), t.turn_radius) << cmd;
        for (const std::string& f : kTurnaround) EXPECT_EQ(lists(r.out, f), t.turnaround) << cmd << " " << f;
        EXPECT_EQ(lists(r.out, "--quiet"), t.quiet) << cmd;
        EXPECT_EQ(lists(r.out, "--digits"), t.digits) << cmd;
        EXPECT_FALSE(lists(r.out, "--body-count")) << cmd;
    }
}

TEST(CliFlags, AFlagNotTakenIsRefusedWithTheReason) {
    const auto a = run_dragon("turnaround --pitch 5 --no-clearance");
    EXPECT_EQ(a.code, 2);
    EXPECT_EQ(count_lines(a.err), 1) << a.err;
    EXPECT_TRUE(contains(a.err, "dragon turnaround does not take --pitch: it runs on the turnaround path")) << a.err;
    const auto b = run_dragon("min-pitch --path turnaround");
    EXPECT_EQ(b.code, 2);
    EXPECT_TRUE(contains(b.err, "dragon min-pitch does not take --path")) << b.err;
    const auto c = run_dragon("solve --path turnaround");
    EXPECT_EQ(c.code, 2);
    EXPECT_TRUE(contains(c.err, "dragon solve does not take --path: it answers Q1-Q3 on the plain spiral")) << c.err;
    // A flag of the other path: --path decides which are read.
    const auto d = run_dragon("simulate --turn-pitch 2 --to 1");
    EXPECT_EQ(d.code, 2);
    EXPECT_TRUE(contains(d.err, "--turn-pitch is not used on the plain spiral: add --path turnaround")) << d.err;
    const auto e = run_dragon("simulate --path turnaround --start-turn 3 --to 1");
    EXPECT_EQ(e.code, 2);
    EXPECT_TRUE(contains(e.err, "--start-turn is not used on the turnaround path")) << e.err;
    EXPECT_EQ(run_dragon("simulate --path turnaround --turn-pitch 2 --to -99").code, 0);
    // The range of the clearance check is nothing without the check.
    const auto f = run_dragon("turnaround --no-clearance --from 3");
    EXPECT_EQ(f.code, 2);
    EXPECT_TRUE(contains(f.err, "--no-clearance")) << f.err;
}

TEST(CliFlags, AValueTheCommandDoesNotReadCannotFailIt) {
    // A pitch narrower than a bench: wrong for the plain spiral, of no concern to min-pitch
    // (it searches the pitch), the turnaround commands, or solve --only q4.
    const std::string file = toml("narrow.toml", "pitch = 0.1\n");
    const auto q3 = run_dragon("min-pitch --scenario " + file + " --lo 0.44 --hi 0.46 --grid 0.01");
    EXPECT_EQ(q3.code, 0) << q3.err;
    EXPECT_TRUE(contains(q3.out, "minimum pitch")) << q3.out;
    const auto q4 = run_dragon("turnaround --no-clearance --scenario " + file);
    EXPECT_EQ(q4.code, 0) << q4.err;
    const auto q5 = run_dragon("max-speed --scenario " + file);
    EXPECT_EQ(q5.code, 0) << q5.err;
    const fs::path out = dragon_test::scratch_dir() / "solve";
    const auto only = run_dragon("solve --only q4 -q -o " + out.string() + " --scenario " + file);
    EXPECT_EQ(only.code, 0) << only.err;
    EXPECT_TRUE(fs::exists(out / "result4.xlsx"));
    // ... but the plain spiral reads it, and says where it came from.
    const auto q1 = run_dragon("simulate --to 1 --scenario " + file);
    EXPECT_EQ(q1.code, 2);
    EXPECT_TRUE(contains(q1.err, "scenario file '" + file + "': pitch 0.1 is not allowed with width 0.3")) << q1.err;
    // A flag for a question --only leaves out would do nothing.
    const auto unused = run_dragon("solve --only q4 -o " + out.string() + " --pitch 0.5");
    EXPECT_EQ(unused.code, 2);
    EXPECT_TRUE(contains(unused.err, "--pitch is not used: no question of --only q4 reads it")) << unused.err;
}

TEST(CliFlags, ABadValueInTheFileNamesTheFile) {
    const std::string file = toml("nan-width.toml", "width = nan\n");
    const auto r = run_dragon("simulate --to 1 --scenario " + file);
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_TRUE(contains(r.err, "scenario file '" + file + "': width = nan is not allowed")) << r.err;
    // A flag overriding the bad value: the file's value is never used.
    EXPECT_EQ(run_dragon("simulate --to 1 --width 0.3 --scenario " + file).code, 0);
}

TEST(CliFlags, BenchCountCountsEveryBench) {
    // Three benches: the head, one body bench and the tail, on four handles.
    const auto r = run_dragon("simulate --bench-count 3 --to 0");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(count_lines(r.out), 1 + 4);
    const auto old = run_dragon("simulate --body-count 3 --to 0");
    EXPECT_EQ(old.code, 2);
    EXPECT_TRUE(contains(old.err, "--body-count: it is now --bench-count")) << old.err;
}

TEST(CliCommandLine, UnknownCommandsAreNamed) {
    const auto typo = run_dragon("simulat");
    EXPECT_EQ(typo.code, 2);
    EXPECT_EQ(count_lines(typo.err), 1) << typo.err;
    EXPECT_TRUE(contains(typo.err, "unknown command 'simulat' (did you mean simulate?)")) << typo.err;
    const auto foo = run_dragon("foo");
    EXPECT_EQ(foo.code, 2);
    EXPECT_TRUE(contains(foo.err, "unknown command 'foo': the commands are simulate, solve")) << foo.err;
    const auto none = run_dragon("");
    EXPECT_EQ(none.code, 2);
    EXPECT_EQ(count_lines(none.err), 1) << none.err;
    EXPECT_TRUE(contains(none.err, "a command is needed")) << none.err;
    const auto help = run_dragon("help");
    EXPECT_EQ(help.code, 0);
    EXPECT_TRUE(contains(help.out, "Usage: dragon")) << help.out;
    EXPECT_TRUE(contains(help.out, "min-pitch")) << help.out;
    const auto help_one = run_dragon("help min-pitch");
    EXPECT_EQ(help_one.code, 0);
    EXPECT_TRUE(contains(help_one.out, "dragon min-pitch")) << help_one.out;
    EXPECT_TRUE(contains(help_one.out, "--grid")) << help_one.out;
}

TEST(CliCommandLine, UnknownOptionsAreNamed) {
    const auto typo = run_dragon("simulate --pich 0.6");
    EXPECT_EQ(typo.code, 2);
    EXPECT_EQ(count_lines(typo.err), 1) << typo.err;
    EXPECT_TRUE(contains(typo.err, "dragon simulate has no option --pich; did you mean --pitch?")) << typo.err;
    const auto stray = run_dragon("simulate 5");
    EXPECT_EQ(stray.code, 2);
    EXPECT_TRUE(contains(stray.err, "unexpected argument '5'")) << stray.err;
}

TEST(CliCommandLine, ClosestChoice) {
    using dragon::cli::closest;
    const std::vector<std::string> commands = {"simulate", "solve", "collide", "min-pitch", "max-speed"};
    EXPECT_EQ(closest("simulat", commands), "simulate");
    EXPECT_EQ(closest("colide", commands), "collide");
    EXPECT_EQ(closest("min", commands), "min-pitch");  // the only one it starts
    EXPECT_EQ(closest("s", commands), "");
    EXPECT_EQ(closest("so", commands), "");  // too short to guess from
    EXPECT_EQ(closest("foo", commands), "");
    EXPECT_EQ(closest("--widht", {"--width", "--pitch"}), "--width");
}
