// The library's errors as data: an input error names the value in the library's own terms, the
// value as given and what is allowed (the CLI words them with its flags); a moment past the end
// of the valid motion carries the jam. (A file that cannot be written is a FileError naming it:
// tests/io/test_atomic_file.cpp.)
#include <gtest/gtest.h>

#include "dragon/analyses.hpp"
#include "dragon/errors.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;

namespace {

template <class Error, class F>
Error caught(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "nothing thrown";
    throw std::logic_error("nothing thrown");
}

}  // namespace

TEST(Errors, InputErrorsNameTheValueInTheLibrarysTerms) {
    const Simulation sim(Scenario{});
    const auto step = caught<InputError>([&] { simulate_table(sim, 0.0, 10.0, -1.0); });
    EXPECT_EQ(step.field(), "time step");
    EXPECT_EQ(step.value(), "-1");
    EXPECT_NE(step.allowed().find("> 0"), std::string::npos);
    EXPECT_EQ(std::string(step.what()), "time step -1 is not allowed: " + step.allowed());

    MinPitchOptions coarse;
    coarse.grid = 0.0;
    const auto grid = caught<InputError>([&] { min_pitch(Scenario{}, 0.4, 0.5, coarse); });
    EXPECT_EQ(grid.field(), "pitch grid");
    EXPECT_EQ(grid.value(), "0");

    Scenario turn;
    turn.path.kind = PathKind::turnaround;
    const auto limit = caught<InputError>([&] { max_head_speed(turn, -2.0); });
    EXPECT_EQ(limit.field(), "speed limit");
    // A value so small it would print with 300 digits in fixed notation reads back short.
    EXPECT_EQ(caught<InputError>([&] { simulate_table(sim, 0.0, 10.0, 1e-300); }).value(), "1e-300");
}

TEST(Errors, AMomentPastTheValidMotionCarriesTheJam) {
    const Simulation sim(Scenario{});
    const auto past = caught<PastTheValidMotion>([&] { first_contact(sim, 0.0, 440.0); });
    EXPECT_EQ(past.field(), "time range end");
    EXPECT_EQ(past.value(), "440");
    EXPECT_TRUE(past.ahead);
    EXPECT_EQ(past.jam.handle, 1);
    EXPECT_EQ(past.jam.kind, JamKind::root_vanishes);
    EXPECT_NEAR(past.jam.time, sim.valid_end(), 1e-12);
    // No library message names a command-line flag.
    EXPECT_EQ(std::string(past.what()).find("--"), std::string::npos) << past.what();
}

