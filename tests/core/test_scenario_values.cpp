// validate() checks the values a computation reads and no others; a scenario's TOML text says
// which values it sets, and its own mistakes ([[dragon]], a stray key) are named. (Files:
// tests/io/test_scenario_file.cpp.)
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "dragon/chain.hpp"
#include "dragon/scenario.hpp"

using namespace dragon;

namespace {

// The message and the values named by validate(s, values), or "" if it accepts.
std::pair<std::string, ScenarioValues> refusal(const Scenario& s, ScenarioValues values) {
    try {
        validate(s, values);
    } catch (const ScenarioError& e) {
        return {e.what(), e.values};
    }
    return {"", 0};
}

}  // namespace

TEST(ScenarioValues, EachPathReadsItsOwn) {
    EXPECT_EQ(values_read(PathKind::spiral), value::bench | value::head_speed | value::pitch | value::start_turn);
    EXPECT_EQ(values_read(PathKind::turnaround),
              value::bench | value::head_speed | value::turn_radius | value::turn_pitch | value::arc_ratio);
}

TEST(ScenarioValues, AValueNotReadIsNotChecked) {
    // A plain-spiral pitch narrower than a bench: the turnaround path never reads it.
    Scenario s;
    s.path.pitch = 0.1;
    s.path.kind = PathKind::turnaround;
    EXPECT_NO_THROW(validate(s));
    EXPECT_NO_THROW(Simulation{s});
    s.path.kind = PathKind::spiral;
    EXPECT_THROW(validate(s), InputError);
    // Q3's values: the pitch is searched, so it is not among them.
    EXPECT_NO_THROW(validate(s, value::bench | value::head_speed | value::start_turn | value::turn_radius));
    // A NaN turn radius is no concern of the plain spiral's simulation.
    Scenario t;
    t.path.turn_radius = std::nan("");
    EXPECT_NO_THROW(Simulation{t});
    EXPECT_EQ(refusal(t, value::all).second, value::turn_radius);
}

TEST(ScenarioValues, RefusalsNameTheValuesOfTheRule) {
    Scenario s;
    s.bench.width = std::nan("");
    auto [what, values] = refusal(s, value::all);
    EXPECT_EQ(values, value::width);
    EXPECT_NE(what.find("width = nan"), std::string::npos) << what;

    s = {};
    s.path.pitch = 0.25;  // not wider than the 0.3 m bench: a rule between two values
    std::tie(what, values) = refusal(s, value::all);
    EXPECT_EQ(values, value::pitch | value::width);
    // Without the width among the values, the rule is not checked.
    EXPECT_EQ(refusal(s, value::pitch).first, "");

    s = {};
    s.bench.hole_offset = std::nan("");
    std::tie(what, values) = refusal(s, value::all);
    EXPECT_EQ(values, value::hole_offset);
    EXPECT_NE(what.find("hole offset = nan is not allowed: it must be a finite number >= 0"), std::string::npos)
        << what;
}

TEST(ScenarioText, SaysWhichValuesItSets) {
    const LoadedScenario loaded =
        parse_scenario_toml("[dragon]\nwidth = 0.25\nbench_count = 5\n[path]\npitch = 0.1\n", "some.toml");
    EXPECT_EQ(loaded.values, value::width | value::bench_count | value::pitch);
    EXPECT_EQ(loaded.scenario.bench.width, 0.25);
    EXPECT_EQ(loaded.scenario.bench.bench_count, 5);
    EXPECT_EQ(loaded.scenario.path.pitch, 0.1);
    EXPECT_EQ(loaded.scenario.bench.head_length, Scenario{}.bench.head_length);  // untouched
}

TEST(ScenarioText, MistakesAreNamed) {
    auto message = [](const std::string& text) {
        try {
            parse_scenario_toml(text, "s.toml");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    const std::string array = message("[[dragon]]\nwidth = 0.3\n");
    EXPECT_NE(array.find("[[dragon]] is not allowed: write its keys at the top level"), std::string::npos) << array;
    const std::string stray = message("pitchh = 0.5\n");
    EXPECT_NE(stray.find("unknown key 'pitchh' (allowed: pitch,"), std::string::npos) << stray;
    const std::string unknown = message("[dragons]\nwidth = 0.3\n");
    EXPECT_NE(unknown.find("unknown section [dragons]"), std::string::npos) << unknown;
}
