// dragon sweep, end to end: every row holds what the single command answers for its scenario
// (run separately, its --json flattened here), refused scenarios and jams are rows that say so,
// bad specs are refused naming them with nothing written, a sweep file says what flags say.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/param_name.hpp"
#include "sweep_support.hpp"

namespace fs = std::filesystem;
using dragon_test::contains;
using dragon_test::count_lines;
using dragon_test::run_dragon;
using dragon_test::slurp;
using json = nlohmann::ordered_json;

namespace {

// The keys of the single commands' --json that a sweep leaves out: the contact's handles and the
// turnaround's length study are tables of their own, not values of the scenario (README).
const std::set<std::string> kTables = {"handles", "length_vs_ratio", "length_vs_entry_radius", "ratio_spread",
                                       "conclusion"};

sweep_test::Table sweep(const std::string& args) {
    const fs::path out = dragon_test::scratch_dir() / "sweep.csv";
    fs::remove(out);
    fs::remove(out.string() + ".partial");  // a run interrupted before this one may have left it
    const dragon_test::CliRun r = run_dragon("sweep -q -o " + out.string() + " " + args);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_FALSE(fs::exists(out.string() + ".partial"));
    return sweep_test::read_table(slurp(out));
}

// The row's cells of `measure` against the command's answer for the same scenario.
void expect_row_is_answer(const std::map<std::string, std::string>& row, const std::string& measure,
                          const std::string& flags, const std::string& command_options = "") {
    const dragon_test::CliRun r = run_dragon(measure + " --json " + flags + " " + command_options);
    ASSERT_EQ(r.code, 0) << flags << "\n" << r.err;
    json answer = json::parse(r.out);
    for (const std::string& t : kTables) answer.erase(t);
    std::map<std::string, std::string> expected;
    sweep_test::flatten(answer, "", expected);
    std::map<std::string, std::string> got;
    for (const auto& [column, cell] : row)
        if (column.rfind(measure + ".", 0) == 0) got[column.substr(measure.size() + 1)] = cell;
    // A null object (no jam) is as many empty cells as it has keys when it is there.
    for (const auto& [key, cell] : got) {
        if (expected.count(key)) continue;
        const std::string parent = key.substr(0, key.rfind('.'));
        EXPECT_TRUE(key.find('.') != std::string::npos && expected.count(parent) && expected[parent].empty())
            << measure << "." << key << " is no key of the command's answer";
        EXPECT_EQ(cell, "") << measure << "." << key;
    }
    for (const auto& [key, cell] : expected) {
        // What the search proved is how it searched, not a value of the scenario: no columns.
        if ((measure == "collide" || measure == "max-speed" || measure == "min-pitch" || measure == "turnaround") &&
            (key.rfind("proof", 0) == 0 || key.rfind("enclosure", 0) == 0))
            continue;
        // Likewise how the valid motion's end was proved, in every measure's jam.
        if (key.rfind("jam.proof", 0) == 0 || key.rfind("jam.enclosure", 0) == 0) continue;
        // Benches overlapping at the start are the row's verdict (collides), not a column.
        if (measure == "collide" && key.rfind("overlap_at_start", 0) == 0) continue;
        if (!got.count(key)) {
            // The object is null in the command's answer: the sweep's columns hold its keys.
            const bool spread = cell.empty() && std::any_of(got.begin(), got.end(), [&](const auto& g) {
                return g.first.rfind(key + ".", 0) == 0;
            });
            EXPECT_TRUE(spread) << measure << " has no column " << key;
            continue;
        }
        if (measure == "collide" && key == "evaluations") continue;  // the work done: it depends on the workers
        if (measure == "collide" && !cell.empty() && (key == "time" || key == "head_radius" || key == "point")) {
            // The search splits its range by the number of workers, so the bisection ends within
            // its stated tolerance (the head moves at 1 m/s: as many metres) of the command's.
            const double tolerance = std::stod(row.at("collide.tolerance"));
            const json a = json::parse(got[key]), b = json::parse(cell);
            for (std::size_t k = 0; k < (a.is_array() ? a.size() : 1); ++k)
                EXPECT_NEAR(a.is_array() ? a[k].get<double>() : a.get<double>(),
                            b.is_array() ? b[k].get<double>() : b.get<double>(), tolerance)
                    << key << " " << flags;
            continue;
        }
        EXPECT_EQ(got[key], cell) << measure << "." << key << " for " << flags;
    }
}

std::string flags_of(const sweep_test::Table& t, std::size_t row, std::size_t axes) {
    std::string out;
    for (std::size_t k = 0; k < axes; ++k) out += " --" + t.header[k] + " " + t.rows[row].at(t.header[k]);
    return out;
}

}  // namespace

TEST(CliSweep, RowsAreTheTurnaroundAndSpeedCommandsAnswers) {
    // Ratio 3: the dragon cannot follow the S-curve (a jam), a row like the others.
    const sweep_test::Table t = sweep("--vary bench-count=20,40 --vary arc-ratio=2,3 --measure turnaround,max-speed");
    ASSERT_EQ(t.rows.size(), 4u);
    EXPECT_EQ(t.header.front(), "bench-count");
    EXPECT_EQ(t.header[1], "arc-ratio");
    EXPECT_EQ(t.header.back(), "status");
    int jams = 0;
    for (std::size_t k = 0; k < t.rows.size(); ++k) {
        expect_row_is_answer(t.rows[k], "turnaround", flags_of(t, k, 2));
        expect_row_is_answer(t.rows[k], "max-speed", flags_of(t, k, 2));
        const std::string& status = t.rows[k].at("status");
        if (t.rows[k].at("arc-ratio") == "3") {
            ++jams;
            EXPECT_TRUE(contains(status, "jam (max-speed)")) << status;
            EXPECT_TRUE(contains(status, "jam (turnaround)")) << status;
            EXPECT_EQ(t.rows[k].at("turnaround.followable"), "false");
        } else {
            EXPECT_EQ(status, "ok");
        }
    }
    EXPECT_EQ(jams, 2);
}

TEST(CliSweep, RowsAreTheCollideAndMinPitchCommandsAnswers) {
    const sweep_test::Table c = sweep("--vary bench-count=20,40 --vary width=0.25,0.3 --measure collide");
    ASSERT_EQ(c.rows.size(), 4u);
    for (std::size_t k = 0; k < c.rows.size(); ++k) expect_row_is_answer(c.rows[k], "collide", flags_of(c, k, 2));
    // min-pitch's range follows the width: width+0.12 is 0.4 m at width 0.28.
    const sweep_test::Table m =
        sweep("--vary width=0.28,0.3 --measure min-pitch --bench-count 30 --lo width+0.12 --hi width+0.18 --grid 0.01");
    ASSERT_EQ(m.rows.size(), 2u);
    for (std::size_t k = 0; k < m.rows.size(); ++k) {
        const bool narrow = m.rows[k].at("width") == "0.28";
        expect_row_is_answer(m.rows[k], "min-pitch", flags_of(m, k, 1),
                             narrow ? "--bench-count 30 --lo 0.4 --hi 0.46 --grid 0.01"
                                    : "--bench-count 30 --lo 0.42 --hi 0.48 --grid 0.01");
        EXPECT_EQ(m.rows[k].at("status"), "ok");
    }
}

TEST(CliSweep, RefusedScenarioIsARowWithTheCommandsReason) {
    // Width 0.6 against the contest's pitch of 0.55 m: collide refuses it; the sweep goes on.
    const sweep_test::Table t = sweep("--vary width=0.3,0.6 --measure collide --bench-count 20");
    ASSERT_EQ(t.rows.size(), 2u);
    const dragon_test::CliRun single = run_dragon("collide --width 0.6 --bench-count 20");
    ASSERT_EQ(single.code, 2);
    const std::string reason = single.err.substr(std::string("dragon: error: ").size(), single.err.size() - 16);
    for (const auto& row : t.rows) {
        if (row.at("width") == "0.3") {
            EXPECT_EQ(row.at("status"), "ok");
            continue;
        }
        EXPECT_EQ(row.at("status"), "refused (collide): " + reason);
        for (const auto& [column, cell] : row)
            if (column.rfind("collide.", 0) == 0) {
                EXPECT_EQ(cell, "") << column;
            }
    }
}

class SweepBadInput : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

TEST_P(SweepBadInput, ExitTwoNamingItAndNoFile) {
    const fs::path dir = dragon_test::scratch_dir();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    std::string given = GetParam().first;
    if (const std::size_t at = given.find("@DIR"); at != std::string::npos) given.replace(at, 4, dir.string());
    const std::string plot = contains(given, "--plot") ? "" : " --plot " + (dir / "map.png").string();
    const std::string args = "sweep -o " + (dir / "rows.csv").string() + plot + " " + given;
    const dragon_test::CliRun r = run_dragon(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_TRUE(contains(r.err, GetParam().second)) << r.err;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename() != "stderr.txt" && e.path().filename() != "stdout.txt") ADD_FAILURE() << e.path();
}

INSTANTIATE_TEST_SUITE_P(
    Cli, SweepBadInput,
    ::testing::Values(std::pair{"--vary width=0.2:0.4 --measure collide", "width=0.2:0.4"},
                      std::pair{"--vary width=0.2:0.4:two --measure collide", "width=0.2:0.4:two"},
                      std::pair{"--vary colour=1,2 --measure collide", "colour=1,2"},
                      std::pair{"--vary width=0.3,0.3 --measure collide", "width=0.3,0.3"},
                      std::pair{"--vary bench-count=10:11:3 --measure collide", "bench-count=10:11:3"},
                      std::pair{"--vary width=nan --measure collide", "width=nan"},
                      std::pair{"--vary pitch=0.5,0.6 --measure min-pitch", "min-pitch does not read the pitch"},
                      std::pair{"--vary width=0.3,0.4 --measure bogus", "--measure bogus"},
                      std::pair{"--vary width=0.3,0.4", "--measure"},
                      std::pair{"--measure collide", "--vary"},
                      std::pair{"--vary width=0.3,0.4 --measure collide --width 0.3", "--width"},
                      std::pair{"--vary width=0.3,0.4 --measure collide --limit 3", "--limit 3"},
                      std::pair{"--vary width=0.3,0.4 --measure max-speed --pitch 0.6", "--pitch"},
                      std::pair{"--vary width=0.3,0.4 --measure min-pitch --lo width-0.1", "--lo width-0.1"},
                      std::pair{"--vary width=0.3,0.4 --measure collide --shard 0/2", "--shard 0/2"},
                      std::pair{"--vary width=0.3 --measure collide", "--plot"},
                      std::pair{"--vary width=0.3,0.4 --measure collide --plot @DIR/map.jpg", "use .png, .svg or .pdf"},
                      std::pair{"--vary width=0.3,0.4 --measure collide --workers 0", "--workers 0"}),
    [](const auto& info) { return dragon_test::param_name(info.index, info.param.first); });

TEST(CliSweep, JsonRowsAndASweepFileSayWhatTheFlagsSay) {
    const fs::path dir = dragon_test::scratch_dir();
    const sweep_test::Table flags = sweep("--vary arc-ratio=1.5,2 --measure max-speed --bench-count 20 --limit 1.8");
    std::ofstream(dir / "spec.toml") << "measure = \"max-speed\"\nvary = [\"arc_ratio=1.5,2\"]\n"
                                        "[fixed]\nbench_count = 20\n[max-speed]\nlimit = 1.8\n";
    const sweep_test::Table file = sweep((dir / "spec.toml").string());
    EXPECT_EQ(file.spec, flags.spec);
    EXPECT_EQ(file.header, flags.header);
    EXPECT_EQ(sweep_test::row_set(file), sweep_test::row_set(flags));
    // --json: one object a row, the varied values, each measure's answer, the status.
    const dragon_test::CliRun r = run_dragon("sweep -q --json " + (dir / "spec.toml").string());
    ASSERT_EQ(r.code, 0) << r.err;
    ASSERT_EQ(count_lines(r.out), 2);
    for (const std::string& line : sweep_test::lines(r.out)) {
        const json row = json::parse(line);
        EXPECT_EQ(row.size(), 3u);
        EXPECT_TRUE(row.contains("arc-ratio"));
        EXPECT_EQ(row.at("max-speed").at("limit"), 1.8);
        EXPECT_EQ(row.at("status"), "ok");
    }
}
