// Extreme but valid scenarios end to end: each works, or is refused with one line and exit
// code 2. Never a crash, a hang, a NaN or a silent wrong answer. (The slow ones, such as the
// first contact of 10,000 benches, are in docs/bad-inputs.md, not here: the suite must stay fast.)
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;

using dragon_test::CliRun;
using dragon_test::slurp;

namespace {

CliRun dragon(const std::string& args) { return dragon_test::run_dragon(args); }

int lines(const std::string& s) { return dragon_test::count_lines(s); }

bool has(const std::string& text, const std::string& word) { return text.find(word) != std::string::npos; }

// A run that must work: exit 0 and no NaN or infinity anywhere in what it printed.
void expect_works(const CliRun& r, const std::string& args) {
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    for (const char* bad : {"nan", "inf"}) EXPECT_FALSE(has(r.out, bad)) << args << "\n" << r.out.substr(0, 400);
}

// A run that must be refused: exit 2, one line on stderr naming `word`.
void expect_refused(const CliRun& r, const std::string& args, const std::string& word) {
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(lines(r.err), 1) << args << "\n" << r.err;
    EXPECT_TRUE(has(r.err, word)) << args << "\n" << r.err;
}

void works(const std::string& args) { expect_works(dragon(args), args); }
void refused(const std::string& args, const std::string& word) { expect_refused(dragon(args), args, word); }

std::string out_file(const std::string& name) { return (dragon_test::scratch_dir() / name).string(); }

}  // namespace

TEST(Extremes, OneBench) {
    const CliRun sim = dragon("simulate --bench-count 1 --to 3");
    expect_works(sim, "simulate --bench-count 1");
    EXPECT_EQ(lines(sim.out), 1 + 4 * 2);  // header, then 4 frames of 2 handles
    const CliRun hit = dragon("collide --bench-count 1");
    expect_works(hit, "collide --bench-count 1");
    EXPECT_TRUE(has(hit.out, "no collision")) << hit.out;
    works("render --bench-count 1 --time 10 --size 64x64 -o " + out_file("one.png"));
    works("video --bench-count 1 --to 2 --size 64x48 --fps 5 -o " + out_file("one.mp4"));
    // One bench cannot touch another: there is no first contact to draw or film.
    refused("render --bench-count 1 --collision --size 64x64 -o " + out_file("hit.png"), "no two benches touch");
    refused("video --bench-count 1 --size 64x48 -o " + out_file("hit.mp4"), "no two benches touch");
}

TEST(Extremes, TenThousandBenches) {
    const CliRun sim = dragon("simulate --bench-count 10000 --to 0");
    expect_works(sim, "simulate --bench-count 10000");
    EXPECT_EQ(lines(sim.out), 1 + 10001);
    works("render --bench-count 10000 --time 10 --size 64x64 -o " + out_file("long.png"));
    // A million 20 m boards would reach 2e7 m along the spiral, where positions lose precision.
    refused("simulate --bench-count 1000000 --body-length 20 --to 0", "at most");
}

TEST(Extremes, PitchJustAboveTheWidth) {
    works("simulate --pitch 0.3000001 --to 1");
    // The boards overlap from the first instant: there is no first contact after t = 0. That is
    // a verdict on the scenario (exit 0, the benches and how deep), not a refusal.
    const CliRun overlap = dragon("collide --pitch 0.3000001");
    expect_works(overlap, "collide --pitch 0.3000001");
    EXPECT_TRUE(has(overlap.out, "already overlap at 0 m of head travel")) << overlap.out;
    const CliRun json = dragon("collide --pitch 0.3000001 --json");
    expect_works(json, "collide --pitch 0.3000001 --json");
    EXPECT_TRUE(has(json.out, "\"overlap_at_start\":{\"benches\":[")) << json.out.substr(0, 400);
    works("render --pitch 0.3000001 --collision --size 64x64 -o " + out_file("p.png"));
    refused("simulate --pitch 0.3 --to 1", "pitch");
}

TEST(Extremes, SlowHead) {
    const CliRun sim = dragon("simulate --speed 1e-6 --to 300 --step 100");
    expect_works(sim, "simulate --speed 1e-6");
    EXPECT_TRUE(has(sim.out, "\n300,0,8.799997,-0.000300,0.000001\n")) << sim.out.substr(0, 300);
    // The windows are head travel: 100 m either side of the turn at any speed, so the answers
    // are those of 1 m/s, their times a million times later.
    const CliRun slow_q5 = dragon("max-speed --speed 1e-6 --json");
    const CliRun q5 = dragon("max-speed --json");
    expect_works(slow_q5, "max-speed --speed 1e-6");
    const auto a = nlohmann::json::parse(slow_q5.out), b = nlohmann::json::parse(q5.out);
    EXPECT_EQ(a.at("max_head_speed"), b.at("max_head_speed"));
    EXPECT_EQ(a.at("travel"), b.at("travel"));
    EXPECT_NEAR(a.at("time").get<double>() * 1e-6, b.at("time").get<double>(), 1e-12);
    const CliRun turn = dragon("turnaround --speed 1e-6 --json");
    expect_works(turn, "turnaround --speed 1e-6");
    const auto clear = nlohmann::json::parse(turn.out).at("clearance");
    const auto clear_ref = nlohmann::json::parse(dragon("turnaround --json").out).at("clearance");
    EXPECT_EQ(clear.at("distance"), clear_ref.at("distance")) << turn.out;
    EXPECT_EQ(clear.at("benches"), clear_ref.at("benches")) << turn.out;
    works("video --speed 1e-6 --to 100 --size 64x48 --fps 5 --speedup 50 -o " + out_file("slow.mp4"));
    // The first contact, 4.1e8 s away: found as quickly as at 1 m/s (it once crept in 1 s steps),
    // at the same head travel, to the digits a time that large holds.
    auto time_of = [](const CliRun& r) {
        const auto j = nlohmann::json::parse(r.out, nullptr, false);
        return j.is_object() && j.contains("time") && j["time"].is_number() ? j["time"].get<double>() : NAN;
    };
    const CliRun ref = dragon("collide --json");
    const CliRun slow = dragon("collide --speed 1e-6 --json");
    expect_works(slow, "collide --speed 1e-6");
    EXPECT_NEAR(time_of(slow) * 1e-6, time_of(ref), 1e-12 * time_of(ref)) << slow.out.substr(0, 200);
    works("render --speed 1e-6 --collision --size 64x64 -o " + out_file("slow.png"));
}

TEST(Extremes, FastHead) {
    // Where the benches are depends only on how far the head has come: 100 times faster, the
    // first contact comes 100 times sooner (412.473837682 s at 1 m/s).
    const CliRun hit = dragon("collide --speed 100 --json");
    expect_works(hit, "collide --speed 100");
    EXPECT_NEAR(nlohmann::json::parse(hit.out).at("time").get<double>(), 4.12473837682, 1e-10) << hit.out;
    // And 100 times sooner the dragon can no longer follow the spiral (432.917924228 s at 1 m/s).
    refused("simulate --speed 100 --to 5", "until t = 4.329179242");
    const CliRun turn = dragon("turnaround --speed 100");
    expect_works(turn, "turnaround --speed 100");
    EXPECT_TRUE(has(turn.out, "smallest 0.279043 m, benches 1 and 17 at t = 0.301599 s")) << turn.out;
    // A window of seconds at that speed is that much head travel: -1..1 s is the same 200 m.
    const CliRun seconds = dragon("turnaround --speed 100 --from -1 --to 1");
    EXPECT_TRUE(has(seconds.out, "smallest 0.279043 m, benches 1 and 17 at t = 0.301599 s")) << seconds.out;
    // 2,000 km of path to scan: refused rather than minutes of work.
    refused("max-speed --speed 1e4 --from -100 --to 100", "--from/--to -1000000..1000000 m of head travel is not allowed");
}

TEST(Extremes, PastTheCollision) {
    const CliRun late = dragon("collide --from 420");
    expect_works(late, "collide --from 420");
    EXPECT_TRUE(has(late.out, "already overlap at t = 420 s")) << late.out;
    EXPECT_TRUE(has(late.out, "an earlier --from finds it")) << late.out;
    refused("video --from 420 --size 64x48 -o " + out_file("late.mp4"), "the first contact, bench 1 touching bench 9, "
                                                                          "is at t = 412.473837682 s, before it");
    // The dragon cannot follow the spiral to its centre: handle 1 loses its root at 432.917924228 s
    // (its speed has no bound there). Up to that moment it works; past it, and past the centre, it is refused.
    works("simulate --from 432.9 --to 432.917924228");
    works("render --time 432.9 --size 64x64 -o " + out_file("late.png"));
    refused("simulate --from 442.5902564 --to 442.5902564", "until t = 432.917924228 s, where handle 1");
    refused("render --time 442.59 --size 64x64 -o " + out_file("centre.png"), "handle 1 can no longer follow");
    refused("simulate --to 443", "until t = 432.917924228");
    refused("collide --from 500", "until t = 432.917924228");
    refused("simulate --to 1e6", "until t = 432.917924228");
}

TEST(Extremes, TurningSpaceWiderThanTheStart) {
    // The head starts at radius 8.8 m, already inside a 20 m turning space.
    refused("video --turn-radius 20 --to boundary --size 64x48 -o " + out_file("b.mp4"), "already inside");
    refused("min-pitch --turn-radius 20 --lo 0.4 --hi 0.45", "inside the turning space");
    const CliRun turn = dragon("turnaround --turn-radius 20 --no-clearance --json");
    expect_works(turn, "turnaround --turn-radius 20");
    EXPECT_EQ(nlohmann::json::parse(turn.out).at("max_radius").get<double>(), 20.0) << turn.out.substr(0, 300);
    works("simulate --path turnaround --turn-radius 20 --to -99");
}

TEST(Extremes, ValuesOutOfRange) {
    refused("simulate --start-turn 1e5 --to 1", "start turn");
    refused("simulate --pitch 2000 --to 1", "pitch");
    refused("simulate --speed 1e10 --to 0", "head speed");
    refused("simulate --hole-offset 1.0999 --body-length 2.2 --to 0", "hole offset");
    refused("simulate --path turnaround --from 1e7 --to 1e7", "--from");
}
