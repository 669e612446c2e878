// The end of the valid motion, end to end: moments past it are refused by every command that
// shows one (exit 2, one line naming the time, the handle and what happens); analyses whose
// range it cuts short say so in their answer (text, and --json "jam"), never a number from
// past it. Ranges at the edge of a search say which side the answer lies on.
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"

namespace fs = std::filesystem;
using dragon_test::contains;
using dragon_test::count_lines;
using dragon_test::run_dragon;
using dragon_test::slurp;
using nlohmann::json;

namespace {

// The contest's spiral: handle 1 loses its root at 432.917924228 s; the turnaround at ratio 3:
// a nearer root is born behind the head at 15.147712683 s (tests/core/test_valid_motion.cpp
// checks both against an independent search).
constexpr const char* kSpiralEnd = "432.917924228";
constexpr const char* kRatio3End = "15.14771268";

void expect_refused(const std::string& args, const std::string& word) {
    const dragon_test::CliRun r = run_dragon(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << args << "\n" << r.err;
    EXPECT_TRUE(contains(r.err, word)) << args << "\n" << r.err;
}

json answer(const std::string& args) {
    const dragon_test::CliRun r = run_dragon(args);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    EXPECT_EQ(count_lines(r.out), 1) << args;
    return json::parse(r.out, nullptr, false);
}

std::string out_file(const std::string& name) { return (dragon_test::scratch_dir() / name).string(); }

}  // namespace

TEST(CliValidMotion, MomentsPastTheEndAreRefused) {
    const std::string where = std::string("until t = ") + kSpiralEnd + " s, where handle 1 can no longer follow handle 0";
    expect_refused("simulate --from 432.9 --to 432.93 --step 0.01", where);
    expect_refused("render --time 433 --size 64x64 -o " + out_file("late.png"), where);
    expect_refused("video --from 430 --to 433 --size 64x48 -o " + out_file("late.mp4"), where);
    expect_refused("simulate --path turnaround --arc-ratio 3 --from 15.1477 --to 15.1478 --step 0.00001",
                   std::string("until t = ") + kRatio3End);
    EXPECT_FALSE(fs::exists(out_file("late.png")));
    EXPECT_FALSE(fs::exists(out_file("late.mp4")));
    // Up to it, the tables are continuous: handle 1 backs up (a negative speed) ever faster.
    const dragon_test::CliRun r = run_dragon("simulate --from 432.9 --to 432.917 --step 0.001");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "\n432.917,1,")) << r.out.substr(0, 200);
    const auto at = r.out.find("\n432.917,1,");
    const std::string row = r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
    EXPECT_LT(std::stod(row.substr(row.rfind(',') + 1)), -5.0) << row;
}

TEST(CliValidMotion, AFilmToTheEndStopsWhereTheMotionEnds) {
    const dragon_test::CliRun r = run_dragon("video --from 432 --to end --speedup 1 --fps 5 --size 64x48 -o " +
                                             out_file("end.mp4"));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(contains(r.err + r.out, "432.917924")) << r.out << r.err;
}

TEST(CliValidMotion, CollideSaysWhereTheSearchEnded) {
    // Ratio 3: no two benches touch before the motion ends at 15.147712683 s.
    const json j = answer("collide --path turnaround --arc-ratio 3 --from -100 --to 100 --json");
    EXPECT_TRUE(j.at("time").is_null());
    ASSERT_TRUE(j.at("jam").is_object()) << j.dump();
    EXPECT_NEAR(j["jam"].at("time").get<double>(), 15.147712683, 1e-9);
    EXPECT_EQ(j["jam"].at("handle"), 1);
    EXPECT_EQ(j["jam"].at("kind"), "nearer_root");
    EXPECT_NEAR(j.at("to").get<double>(), 15.147712683, 1e-9);
    const dragon_test::CliRun text = run_dragon("collide --path turnaround --arc-ratio 3 --from -100 --to 100");
    EXPECT_TRUE(contains(text.out, "the search ends there: the dragon can follow its path only until t = 15.14771268"))
        << text.out;
    // A wide pitch: no contact before the dragon stops following the spiral.
    const json wide = answer("collide --pitch 0.7 --json");
    EXPECT_TRUE(wide.at("time").is_null());
    EXPECT_EQ(wide.at("jam").at("kind"), "root_vanishes");
    // The contest's: the contact comes first, no jam.
    EXPECT_TRUE(answer("collide --json").at("jam").is_null());
}

TEST(CliValidMotion, CollideRefusesRangesThatMeanNothing) {
    expect_refused("collide --from 100 --to 50", "--to 50 is not allowed: it must be after the start, 100");
    expect_refused("collide --to inf", "--to inf is not allowed");
    expect_refused("collide --from 500", std::string("until t = ") + kSpiralEnd);
}

TEST(CliValidMotion, CollideWithNoContactStillWritesItsAnswer) {
    // An old file from another run must not be left looking like this run's answer.
    const std::string csv = out_file("c.csv");
    ASSERT_EQ(run_dragon("collide -o " + csv).code, 0);
    ASSERT_GT(count_lines(slurp(csv)), 200);  // the contest's contact: 224 handles
    const dragon_test::CliRun r = run_dragon("collide --pitch 0.7 -o " + csv);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(slurp(csv), "t,handle,x,y,speed\n");
    EXPECT_TRUE(contains(r.err, "no contact: wrote")) << r.err;
}

TEST(CliValidMotion, MaxSpeedNeverUsesSpeedsFromPastTheEnd) {
    // Ratio 3: the search stops at the nearer root; the largest speed before it is an answer
    // for that stretch only, and says so; a window cut short has no largest head speed (the turn
    // cannot be made at any speed).
    const json cut = answer("max-speed --arc-ratio 3 --json");
    EXPECT_TRUE(cut.at("max_head_speed").is_null());
    EXPECT_NEAR(cut.at("to").get<double>(), 15.147712683, 1e-9);
    EXPECT_EQ(cut.at("jam").at("handle"), 1);
    EXPECT_FALSE(cut.at("unbounded").get<bool>());
    EXPECT_LT(cut.at("ratio").get<double>(), 1.2);  // not the 67310 of a teleporting handle
    // A 6 m head on equal arcs: handle 1's root vanishes on the way; its speed has no bound, so
    // no head speed keeps every handle under the limit.
    const json none = answer("max-speed --head-length 6 --arc-ratio 1 --json");
    EXPECT_TRUE(none.at("unbounded").get<bool>());
    EXPECT_TRUE(none.at("max_head_speed").is_null());
    EXPECT_TRUE(none.at("ratio").is_null());
    EXPECT_EQ(none.at("jam").at("kind"), "root_vanishes");
    const dragon_test::CliRun text = run_dragon("max-speed --head-length 6 --arc-ratio 1");
    EXPECT_TRUE(contains(text.out, "No head speed keeps every handle at or under 2 m/s")) << text.out;
    // The contest's turn is followed all the way: the answer is unchanged.
    const json q5 = answer("max-speed --json");
    EXPECT_NEAR(q5.at("max_head_speed").get<double>(), 1.246266, 1e-6);
    EXPECT_TRUE(q5.at("jam").is_null());
}

TEST(CliValidMotion, TheTurnaroundStudySaysWhichTurnsThisDragonCanFollow) {
    const json j = answer("turnaround --arc-ratio 3 --json");
    EXPECT_FALSE(j.at("followable").get<bool>());
    EXPECT_NEAR(j.at("jam").at("time").get<double>(), 15.147712683, 1e-9);
    EXPECT_NEAR(j.at("clearance").at("to").get<double>(), 15.147712683, 1e-9);
    int usable = 0;
    for (const json& row : j.at("length_vs_ratio")) {
        usable += row.at("followable").get<bool>();
        EXPECT_EQ(row.at("followable").get<bool>(), row.at("jam").is_null());
        if (row.at("ratio").get<double>() == 2.0) {
            EXPECT_TRUE(row.at("followable").get<bool>());
        }
        if (row.at("ratio").get<double>() == 3.0) {
            EXPECT_FALSE(row.at("followable").get<bool>());
        }
    }
    EXPECT_GT(usable, 0);
    EXPECT_TRUE(contains(j.at("conclusion").get<std::string>(), "can follow it only at ratios"));
    // The contest's design is followable, and its clearance unchanged.
    const json q4 = answer("turnaround --json");
    EXPECT_TRUE(q4.at("followable").get<bool>());
    EXPECT_TRUE(q4.at("jam").is_null());
    EXPECT_NEAR(q4.at("clearance").at("distance").get<double>(), 0.279043, 1e-6);
}

TEST(CliValidMotion, MinPitchSaysWhichSideOfTheRangeTheAnswerIsOn) {
    // Every pitch in 0.46..0.5 m is collision-free: the answer is at or below 0.46 m, not 0.46.
    const json below = answer("min-pitch --lo 0.46 --hi 0.5 --json");
    EXPECT_TRUE(below.at("pitch").is_null());
    EXPECT_TRUE(below.at("below_range").get<bool>());
    EXPECT_FALSE(below.at("above_range").get<bool>());
    const json above = answer("min-pitch --lo 0.36 --hi 0.4 --json");
    EXPECT_TRUE(above.at("pitch").is_null());
    EXPECT_TRUE(above.at("above_range").get<bool>());
    const dragon_test::CliRun text = run_dragon("min-pitch --lo 0.46 --hi 0.5");
    EXPECT_TRUE(contains(text.out, "lies at or below it")) << text.out;
    // Across the change the pitch is printed to the digits it resolves.
    const dragon_test::CliRun hit = run_dragon("min-pitch --lo 0.445 --hi 0.455");
    EXPECT_TRUE(contains(hit.out, "minimum pitch: 0.4503373")) << hit.out;
    EXPECT_TRUE(std::regex_search(hit.out, std::regex("minimum pitch: 0\\.[0-9]{10} m"))) << hit.out;
}

// The advice of an answer below the range can be followed: it names how far --lo may go down,
// and a --lo there is accepted (the head starts at radius start-turn x pitch: 0.45 m is the
// edge of a 4.5 m turning space at start turn 10); a range that starts lower is refused as
// --lo, with the same bound.
TEST(CliValidMotion, MinPitchAdviceCanBeFollowed) {
    const dragon_test::CliRun below = run_dragon("min-pitch --start-turn 10 --lo 0.451");
    ASSERT_EQ(below.code, 0) << below.err;
    EXPECT_TRUE(contains(below.out, "lower --lo to find it, keeping it above 0.45 m")) << below.out;
    EXPECT_EQ(run_dragon("min-pitch --start-turn 10 --lo 0.4501").code, 0);
    expect_refused("min-pitch --start-turn 10 --lo 0.45", "--lo 0.45 is not allowed");
    expect_refused("min-pitch --start-turn 10 --lo 0.35", "a pitch above 0.45 m starts the head outside it");
    // Within the tolerance of the bound there is nothing lower to search, and no advice to.
    const dragon_test::CliRun edge = run_dragon("min-pitch --start-turn 10 --lo 0.4500000005");
    ASSERT_EQ(edge.code, 0) << edge.err;
    EXPECT_FALSE(contains(edge.out, "lower --lo")) << edge.out;
    EXPECT_TRUE(contains(edge.out, "there is no lower pitch to search")) << edge.out;
}

// The same input, the same bytes: the refusal (once a race between the pitches run in
// parallel, naming 0.35 or 0.3525) and an answer narrowed by k-section (whose points were
// one per worker), each run several times.
TEST(CliValidMotion, MinPitchPrintsTheSameBytesEveryRun) {
    for (const std::string args : {"min-pitch --start-turn 10 --lo 0.35",
                                   "min-pitch --turn-radius 1.2 --lo 0.85 --hi 0.95 --grid 0.01"}) {
        const dragon_test::CliRun first = run_dragon(args);
        for (int k = 0; k < 6; ++k) {
            const dragon_test::CliRun again = run_dragon(args);
            EXPECT_EQ(again.code, first.code) << args;
            EXPECT_EQ(again.out, first.out) << args;
            EXPECT_EQ(again.err, first.err) << args;
        }
    }
}

TEST(CliValidMotion, MinPitchNamesRunsThatCannotReachTheBoundary) {
    // A turning space of radius 1 m: wide pitches coil in without contact, but the dragon stops
    // following the spiral before its head gets there.
    const json j = answer("min-pitch --turn-radius 1 --lo 0.7 --hi 0.8 --grid 0.05 --json");
    EXPECT_TRUE(j.at("above_range").get<bool>());
    ASSERT_TRUE(j.at("jam").is_object()) << j.dump();
    EXPECT_EQ(j["jam"].at("pitch").get<double>(), 0.8);
    EXPECT_EQ(j["jam"].at("kind"), "root_vanishes");
}
