// One dragon, one answer, end to end: the commands' geometric answers do not depend on the head's
// speed, two commands asked the same question agree, and solve answers every scenario the
// single commands accept, saying where the valid motion cut a question short.
#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"

namespace fs = std::filesystem;
using dragon_test::contains;
using dragon_test::run_dragon;
using dragon_test::slurp;
using nlohmann::json;

namespace {

json answer(const std::string& args) {
    const dragon_test::CliRun r = run_dragon(args);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    const json j = json::parse(r.out, nullptr, false);
    EXPECT_TRUE(j.is_object()) << args << "\n" << r.out;
    return j;
}

}  // namespace

TEST(CliOneAnswer, TheLargestHeadSpeedIsTheSameAtEveryHeadSpeed) {
    // Was 1.799898 m/s at 0.1 m/s and 2.000000 m/s at 0.05 m/s: the window was 100 s, 5 m of path.
    const json ref = answer("max-speed --json");
    for (const char* v : {"0.05", "0.1", "5"}) {
        const json a = answer(std::string("max-speed --json --speed ") + v);
        EXPECT_EQ(a["max_head_speed"], ref["max_head_speed"]) << v;
        EXPECT_EQ(a["tied"], ref["tied"]) << v;
        EXPECT_EQ(a["travel"], ref["travel"]) << v;
        EXPECT_EQ(a["from_travel"], -100.0) << v;
        EXPECT_EQ(a["to_travel"], 100.0) << v;
        EXPECT_DOUBLE_EQ(a["time"].get<double>() * std::stod(v), ref["time"].get<double>()) << v;
    }
    // And a sweep over the speed measures the same thing on every row.
    const dragon_test::CliRun sweep = run_dragon("sweep --vary speed=0.05,0.1,1,5 --measure max-speed --json -q");
    ASSERT_EQ(sweep.code, 0) << sweep.err;
    std::istringstream rows(sweep.out);
    int n = 0;
    for (std::string line; std::getline(rows, line); ++n) {
        const json row = json::parse(line);
        EXPECT_EQ(row["max-speed"]["max_head_speed"], ref["max_head_speed"]) << line;
        EXPECT_EQ(row["status"], "ok") << line;
    }
    EXPECT_EQ(n, 4);
}

TEST(CliOneAnswer, ASlowHeadDoesNotMakeACollidingTurnCollisionFree) {
    // At turn pitch 0.5 the benches touch 12.87 m into the turn; 100 s at 0.05 m/s was 5 m.
    const json fast = answer("turnaround --turn-pitch 0.5 --json");
    const json slow = answer("turnaround --turn-pitch 0.5 --speed 0.05 --json");
    ASSERT_TRUE(fast["first_contact"].is_object()) << fast.dump();
    ASSERT_TRUE(slow["first_contact"].is_object()) << slow.dump();
    EXPECT_EQ(slow["first_contact"]["travel"], fast["first_contact"]["travel"]);
    EXPECT_EQ(slow["first_contact"]["benches"], fast["first_contact"]["benches"]);
    EXPECT_FALSE(slow["clearance"]["collision_free"].get<bool>());
}

TEST(CliOneAnswer, CollideAndTurnaroundReportOneFirstContact) {
    const json c = answer("collide --path turnaround --turn-pitch 0.44 --json");
    const json t = answer("turnaround --turn-pitch 0.44 --json");
    ASSERT_TRUE(t["first_contact"].is_object());
    for (const char* key : {"time", "travel", "benches", "point", "head_radius", "tolerance"})
        EXPECT_EQ(c[key], t["first_contact"][key]) << key;
    EXPECT_EQ(c["from_travel"], -100.0);
    EXPECT_EQ(c["to_travel"], 100.0);
    // A window can be given in seconds or in metres of head travel, and says both.
    const json seconds = answer("collide --path turnaround --turn-pitch 0.44 --speed 2 --from -50 --to 50 --json");
    const json metres = answer("collide --path turnaround --turn-pitch 0.44 --speed 2 --json");
    EXPECT_EQ(seconds["travel"], c["travel"]);
    EXPECT_EQ(metres["travel"], c["travel"]);
    EXPECT_EQ(seconds["from"], -50.0);
    EXPECT_EQ(metres["from"], -50.0);
    // The smallest clearance is never a negative "clearance" past the contact.
    EXPECT_EQ(t["clearance"]["distance"], 0.0);
    EXPECT_EQ(t["clearance"]["time"], c["time"]);
}

TEST(CliOneAnswer, SolveAnswersWhatTheSingleCommandsAnswer) {
    const fs::path dir = dragon_test::scratch_dir();
    // Ratio 3: the S-curve jams 15.15 s into the turn. Every file is written; the text says
    // where Q4's table and Q5's search end, and the summary says what was left out.
    const dragon_test::CliRun r = run_dragon("solve --arc-ratio 3 -o " + (dir / "r3").string());
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* f : {"result1.xlsx", "result2.xlsx", "result4.xlsx", "summary.json"})
        EXPECT_TRUE(fs::exists(dir / "r3" / f)) << f;
    EXPECT_TRUE(contains(r.out, "85 rows of -100..100 s left out: the dragon can follow its path only until t = "
                                "15.1477126")) << r.out;
    // No largest speed for a turn the dragon cannot make at any speed: the verdict instead.
    EXPECT_TRUE(contains(r.out, "Q5: no head speed makes this turn")) << r.out;
    const json summary = json::parse(slurp(dir / "r3" / "summary.json"));
    EXPECT_EQ(summary["q4"]["rows_left_out"], 85);
    EXPECT_EQ(summary["q4"]["followable"], false);
    EXPECT_TRUE(summary["q5"]["jam"].is_object());
    EXPECT_TRUE(summary["q5"]["max_head_speed"].is_null());
    // --only q5 says it too.
    const dragon_test::CliRun q5 = run_dragon("solve --arc-ratio 3 --only q5 -o " + (dir / "q5").string());
    ASSERT_EQ(q5.code, 0) << q5.err;
    EXPECT_TRUE(contains(q5.out, "Q5: no head speed makes this turn")) << q5.out;
    // Start turn 8: the contest's pitches start the head inside the turning space.
    const dragon_test::CliRun late = run_dragon("solve --start-turn 8 -o " + (dir / "s8").string());
    ASSERT_EQ(late.code, 0) << late.err;
    EXPECT_TRUE(contains(late.out, "below 0.5625 m the head would start inside the turning space")) << late.out;
    EXPECT_TRUE(fs::exists(dir / "s8" / "result4.xlsx"));
    // Q3's range can be given, as min-pitch takes it.
    const dragon_test::CliRun q3 = run_dragon("solve --only q3 --lo 0.44 --hi 0.46 -o " + (dir / "q3").string());
    ASSERT_EQ(q3.code, 0) << q3.err;
    EXPECT_TRUE(contains(q3.out, "minimum pitch 0.4503373935 m")) << q3.out;
}

TEST(CliOneAnswer, OneSentencePerEvent) {
    // The motion on this S-curve begins 1.388 s before the turn: every command words it so.
    const dragon_test::CliRun t = run_dragon("turnaround --turn-radius 0.5");
    const dragon_test::CliRun s = run_dragon("simulate --path turnaround --turn-radius 0.5 --from -10 --to 0");
    EXPECT_EQ(s.code, 2);
    const std::string event = "the dragon can follow its path only from t = -1.388073196 s, where handle 1 can no "
                              "longer follow handle 0";
    EXPECT_TRUE(contains(t.out, event)) << t.out;
    EXPECT_TRUE(contains(s.err, event)) << s.err;
}

TEST(CliOneAnswer, TablesPastTheFirstContactSaySo) {
    const dragon_test::CliRun r = run_dragon("simulate --from 405 --to 415");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(contains(r.err, "rows after t = 412.473837682 s are past the first contact (bench 1 touches bench 9)"))
        << r.err;
    const dragon_test::CliRun before = run_dragon("simulate --from 400 --to 410");
    EXPECT_TRUE(before.err.empty()) << before.err;
}

// max-speed --prove: the JSON's enclosure holds the answer and prints as it does to the six
// decimals the text gives; the human output says it in a line; without --prove the answer is
// the same number and says it is sampled.
TEST(CliOneAnswer, TheProvedLargestSpeedEnclosesTheSampledOne) {
    const auto proved = run_dragon("max-speed --prove --json");
    ASSERT_EQ(proved.code, 0) << proved.err;
    const json p = json::parse(proved.out);
    const double lo = p.at("enclosure").at(0).get<double>(), hi = p.at("enclosure").at(1).get<double>();
    const double v = p.at("max_head_speed").get<double>();
    EXPECT_LE(lo, v);
    EXPECT_GE(hi, v);
    EXPECT_LT(hi - lo, 1e-6);
    EXPECT_EQ(p.at("proof").at("method"), "lipschitz bound");
    EXPECT_EQ(p.at("proof").at("unproved"), 0);
    const auto sampled = run_dragon("max-speed --json");
    ASSERT_EQ(sampled.code, 0) << sampled.err;
    const json s = json::parse(sampled.out);
    EXPECT_EQ(s.at("proof").at("method"), "sampled");
    EXPECT_TRUE(s.at("enclosure").is_null());
    // The proof's points count as found: its ratio is at least the scan's, its speed at most.
    EXPECT_LE(v, s.at("max_head_speed").get<double>());
    EXPECT_LE(lo, s.at("max_head_speed").get<double>());
    const auto text = run_dragon("max-speed --prove");
    EXPECT_TRUE(contains(text.out, "proved: the largest head speed lies in [")) << text.out;
    EXPECT_TRUE(contains(run_dragon("max-speed").out, "not proved: the maximum is the coarse scan's")) << text.out;
}

// solve --prove proves each answer it prints as the single command's --prove does, in the same
// words under each question; without it solve prints no proof; with only Q1 (a table, no
// search) --prove is refused before anything is written.
TEST(CliOneAnswer, SolveProvesEachAnswerAsItsOwnCommandDoes) {
    const fs::path dir = dragon_test::scratch_dir();
    const auto line_of = [](const std::string& text, const std::string& start) {
        const size_t at = text.find(start);
        return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
    };
    const auto proved = run_dragon("solve --prove --only q2,q4,q5 -q -o " + (dir / "a").string());
    ASSERT_EQ(proved.code, 0) << proved.err;
    const std::string q2 = line_of(run_dragon("collide --prove").out, "proved: the first contact lies in");
    ASSERT_FALSE(q2.empty());
    EXPECT_TRUE(contains(proved.out, "\n  " + q2 + "\n")) << proved.out;
    const std::string q5 = line_of(run_dragon("max-speed --prove").out, "proved: the largest head speed lies in");
    ASSERT_FALSE(q5.empty());
    EXPECT_TRUE(contains(proved.out, "\n  " + q5 + "\n")) << proved.out;
    EXPECT_TRUE(contains(proved.out, "\n  the window checked for a contact: proved: no contact over head travel [-100, 100] m"))
        << proved.out;

    // A range wholly feasible: its least pitch is proved on its own quickly there (at the contest's
    // cut that march is seconds of CPU, minutes under the sanitizers; PitchProof's tests prove it).
    const std::string range = "--lo 0.46 --hi 0.47 --grid 0.01";
    const auto q3 = run_dragon("solve --prove --only q3 " + range + " -q -o " + (dir / "b").string());
    ASSERT_EQ(q3.code, 0) << q3.err;
    const std::string own = run_dragon("min-pitch --prove " + range).out;
    for (const char* start : {"proved: every pitch in", "proved: the least feasible pitch of the range lies in"}) {
        const std::string line = line_of(own, start);
        ASSERT_FALSE(line.empty()) << own;
        EXPECT_TRUE(contains(q3.out, "\n  " + line + "\n")) << q3.out;
    }

    const auto plain = run_dragon("solve --only q2,q3,q5 -q -o " + (dir / "c").string());
    ASSERT_EQ(plain.code, 0) << plain.err;
    EXPECT_FALSE(contains(plain.out, "proved")) << plain.out;

    const auto refused = run_dragon("solve --prove --only q1 -o " + (dir / "d").string());
    EXPECT_EQ(refused.code, 2);
    EXPECT_TRUE(contains(refused.err, "--prove is not used")) << refused.err;
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    EXPECT_FALSE(fs::exists(dir / "d"));
}
