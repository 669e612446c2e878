// Where a scenario keeps each of its numbers: the one place the scenario file's reader and the
// sweeps' parameters reach a value by its value:: bit.
#pragma once

#include "dragon/scenario.hpp"

namespace dragon {

// s's number that `v` (one value:: bit) names; nullptr for the bench count (a whole number,
// kept as an int) or no number.
inline double* scenario_number(Scenario& s, ScenarioValues v) {
    if (v == value::pitch) return &s.path.pitch;
    if (v == value::head_speed) return &s.head_speed;
    if (v == value::head_length) return &s.bench.head_length;
    if (v == value::body_length) return &s.bench.body_length;
    if (v == value::width) return &s.bench.width;
    if (v == value::hole_offset) return &s.bench.hole_offset;
    if (v == value::start_turn) return &s.path.start_turn;
    if (v == value::turn_radius) return &s.path.turn_radius;
    if (v == value::turn_pitch) return &s.path.turn_pitch;
    if (v == value::arc_ratio) return &s.path.arc_ratio;
    return nullptr;
}

}  // namespace dragon
