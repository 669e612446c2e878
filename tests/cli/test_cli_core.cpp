// dragon simulate / collide / min-pitch / solve end to end: good runs, and bad input getting one
// clear line, exit code 2 and no file.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <ostream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"
#include "support/param_name.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;

using dragon_test::CliRun;
using dragon_test::slurp;

namespace {

fs::path scratch() { return dragon_test::scratch_dir(); }

CliRun dragon(const std::string& args) { return dragon_test::run_dragon(args); }

int lines(const std::string& s) { return dragon_test::count_lines(s); }

struct BadCase {
    std::string args;
    std::string word;  // the error line must name this
};

// Shown by gtest in failures, instead of the object's bytes.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.args; }

class BadInput : public ::testing::TestWithParam<BadCase> {};

}  // namespace

TEST_P(BadInput, OneLineExitTwoNoFile) {
    const fs::path target = scratch() / "bad-output.csv";
    fs::remove(target);
    std::string args = GetParam().args;
    const auto at = args.find("@OUT");
    if (at != std::string::npos) args.replace(at, 4, target.string());
    const CliRun r = dragon(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("dragon: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(GetParam().word), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(".tmp"), std::string::npos) << r.err;  // never a hidden temporary name
    EXPECT_EQ(r.out, "");
    EXPECT_FALSE(fs::exists(target));
    for (const auto& e : fs::directory_iterator(scratch()))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

INSTANTIATE_TEST_SUITE_P(
    Cli, BadInput,
    ::testing::Values(
        BadCase{"simulate --pitch 0 -o @OUT", "pitch"},
        BadCase{"simulate --pitch -0.5 -o @OUT", "pitch"},
        BadCase{"simulate --pitch nan -o @OUT", "pitch"},
        BadCase{"simulate --speed 0 -o @OUT", "speed"},
        BadCase{"simulate --speed inf -o @OUT", "speed"},
        BadCase{"simulate --head-length -1 -o @OUT", "head length"},
        BadCase{"simulate --body-length 0 -o @OUT", "body length"},
        BadCase{"simulate --width nan -o @OUT", "width"},
        BadCase{"simulate --hole-offset 1.1 -o @OUT", "hole offset"},
        BadCase{"simulate --bench-count 0 -o @OUT", "--bench-count"},
        BadCase{"simulate --pitch 0.25 -o @OUT", "pitch"},  // narrower than a bench: does not fit
        BadCase{"simulate --start-turn 0 -o @OUT", "start turn"},
        BadCase{"simulate --start-turn -3 -o @OUT", "start turn"},
        BadCase{"simulate --to 5000 -o @OUT", "--to"},
        BadCase{"simulate --from 5 --to 1 -o @OUT", "--to"},
        BadCase{"simulate --step 0 -o @OUT", "--step"},
        BadCase{"simulate --bogus 1 -o @OUT", "bogus"},
        BadCase{"simulate --pitch abc -o @OUT", "pitch"},
        BadCase{"simulate --path circle -o @OUT", "circle"},
        BadCase{"simulate --scenario /nonexistent.toml -o @OUT", "nonexistent.toml"},
        BadCase{"simulate -o /nonexistent-dir/out.csv", "nonexistent-dir"},
        BadCase{"simulate -o @OUT.txt", ".txt"},
        BadCase{"collide --pitch 0", "pitch"},
        BadCase{"min-pitch --lo 0.6 --hi 0.5", "range"},
        BadCase{"min-pitch --grid 0", "--grid 0"},
        BadCase{"min-pitch --grid nan", "--grid nan"},
        BadCase{"min-pitch --grid 1e-9", "at most 100000"},
        BadCase{"solve -o /proc/forbidden", "/proc/forbidden"},
        // An empty value is refused, never taken as the default.
        BadCase{"simulate --pitch '' -o @OUT", "--pitch '' is not allowed: give a number"},
        BadCase{"simulate --pitch= -o @OUT", "--pitch '' is not allowed: give a number"},
        BadCase{"simulate -o ''", "--out '' is not allowed: give a file name"},
        BadCase{"solve -o ''", "--out '' is not allowed: give a folder name"},
        BadCase{"collide --to ''", "--to '' is not allowed: give a time in seconds (12.5, or 12.5s) or a length of the head's travel"},
        BadCase{"min-pitch --grid ''", "--grid '' is not allowed: give a number"},
        BadCase{"turnaround -o ''", "--out '' is not allowed: give a file name"},
        BadCase{"max-speed --limit ''", "--limit '' is not allowed: give a number"},
        BadCase{"simulate --scenario '' -o @OUT", "--scenario '' is not allowed: give a .toml file"},
        BadCase{"simulate --path '' -o @OUT", "--path '' is not allowed: use spiral or turnaround"},
        BadCase{"simulate --bench-count '' -o @OUT", "--bench-count '' is not allowed: give a whole number"},
        BadCase{"render --time 1 -o ''", "--out '' is not allowed: give a file name"},
        BadCase{"figures --theme '' -o @OUT", "--theme '' is not allowed: use light, dark or a .toml file"},
        BadCase{"video -o '' --to 1", "--out '' is not allowed: give a file name"},
        // A folder is not a file.
        BadCase{"simulate --scenario / -o @OUT", "scenario file '/' is a folder: give a .toml file"},
        BadCase{"render --time 1 --theme / -o @OUT.png", "theme file '/' is a folder: give a .toml file"},
        // Each command takes the flags it uses, and no others.
        BadCase{"turnaround --pitch 5", "dragon turnaround does not take --pitch"},
        BadCase{"max-speed --start-turn 3", "dragon max-speed does not take --start-turn"},
        BadCase{"min-pitch --pitch 0.1", "dragon min-pitch does not take --pitch"},
        BadCase{"min-pitch --turn-pitch 2", "dragon min-pitch does not take --turn-pitch"},
        BadCase{"solve --path turnaround -o @OUT", "dragon solve does not take --path"},
        BadCase{"figures --path turnaround -o @OUT", "dragon figures does not take --path"},
        BadCase{"simulate --turn-pitch 2 -o @OUT", "--turn-pitch is not used on the plain spiral"},
        BadCase{"simulate --path turnaround --pitch 0.6 -o @OUT", "--pitch is not used on the turnaround path"},
        BadCase{"turnaround --no-clearance --to 5", "--no-clearance and --to cannot be given together"},
        BadCase{"figures --list --scale 2", "--list and --scale cannot be given together"},
        BadCase{"max-speed --digits 3", "dragon max-speed has no option --digits"},
        BadCase{"simulate --body-count 3 -o @OUT", "it is now --bench-count"},
        BadCase{"simulate --bench-count 0 -o @OUT", "--bench-count 0 is not allowed"},
        BadCase{"simulate --pich 0.6 -o @OUT", "did you mean --pitch?"},
        BadCase{"simulat --to 1", "unknown command 'simulat' (did you mean simulate?)"},
        BadCase{"foo", "unknown command 'foo': the commands are simulate, solve, collide"},
        BadCase{"", "a command is needed"},
        // Out of range, named by the flag that put it there; messages in a few digits.
        BadCase{"min-pitch --hi 1e308", "--hi 1e+308 is not allowed: a pitch is at most 1000 m"},
        BadCase{"min-pitch --grid 1e-300", "it makes 2e+299 grid steps"},
        BadCase{"simulate --step 1e-300 -o @OUT", "--step 1e-300 is not allowed: it gives 3e+302 frames"},
        BadCase{"simulate --path turnaround --from 1e300 --to 1e300 -o @OUT", "puts the chain 1e+300 m along"},
        BadCase{"simulate --hole-offset nan -o @OUT", "hole offset = nan is not allowed: it must be a finite number >= 0"},
        BadCase{"simulate --digits 18 -o @OUT", "--digits 18 is not allowed: use 0 to 17"},
        BadCase{"simulate --digits -1 -o @OUT", "--digits -1 is not allowed"},
        BadCase{"simulate --digits 3 -o @OUT.xlsx", "--digits 3 is not allowed with .xlsx"},
        BadCase{"collide --digits 3", "--digits 3 is not allowed without -o"},
        // A target that cannot be written: named (not the hidden temporary file), and why.
        BadCase{"simulate --to 1 -o /proc/x.csv", "output path '/proc/x.csv' is not writable: no file can be made in '/proc'"}),
    [](const auto& info) { return dragon_test::param_name(info.index, info.param.args); });

TEST(Cli, MalformedScenarioFileIsRefused) {
    const fs::path bad = scratch() / "bad.toml", unknown = scratch() / "unknown.toml";
    std::ofstream(bad) << "[dragon\nwidth = 0.3\n";
    std::ofstream(unknown) << "widht = 0.3\n";
    for (const fs::path& f : {bad, unknown}) {
        const CliRun r = dragon("simulate --to 1 --scenario " + f.string());
        EXPECT_EQ(r.code, 2);
        EXPECT_EQ(lines(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(f.filename().string()), std::string::npos) << r.err;
    }
}

TEST(Cli, ScenarioFileAndFlagsOverrideDefaults) {
    // The shipped preset reproduces the defaults; a flag overrides the file.
    const std::string preset = std::string(DRAGON_SOURCE_DIR) + "/assets/cumcm2024.toml";
    const CliRun a = dragon("simulate --to 2");
    const CliRun b = dragon("simulate --to 2 --scenario " + preset);
    ASSERT_EQ(a.code, 0);
    EXPECT_EQ(a.out, b.out);
    const CliRun c = dragon("simulate --to 2 --scenario " + preset + " --pitch 0.6");
    EXPECT_NE(a.out, c.out);
    EXPECT_NE(c.out.find("\n0,0,9.600000,0.000000,1.000000\n"), std::string::npos) << c.out.substr(0, 200);
}

TEST(Cli, SimulateWritesEachFormat) {
    for (const char* ext : {".csv", ".json", ".xlsx"}) {
        const fs::path out = scratch() / (std::string("sim") + ext);
        fs::remove(out);
        const CliRun r = dragon("simulate --from 0 --to 10 --step 2 -o " + out.string());
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_TRUE(fs::exists(out));
        EXPECT_GT(fs::file_size(out), 1000u);
    }
    const std::string csv = slurp(scratch() / "sim.csv");
    EXPECT_EQ(lines(csv), 1 + 6 * 224);
    EXPECT_EQ(csv.rfind("10,223,", std::string::npos) != std::string::npos, true);
}

TEST(Cli, CollideJsonHasTheAgreedKeys) {
    const CliRun r = dragon("collide --json");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(lines(r.out), 1);
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j.at("time").get<double>(), 412.4738, 5e-5);
    EXPECT_EQ(j.at("benches"), nlohmann::json({1, 9}));
    EXPECT_NEAR(j.at("head_radius").get<double>(), 2.288743, 1e-6);
    EXPECT_TRUE(j.at("jam").is_null());  // the contact comes well before the end of the valid motion
}
