// The --json answers of the question commands (collide, min-pitch, turnaround, max-speed), built
// in one place: the commands print them and dragon sweep writes them into its rows, so that a
// sweep's row holds exactly what the single command answers for that scenario.
#pragma once

#include <optional>

#include "cli/report.hpp"
#include "dragon/analyses.hpp"
#include "dragon/turnaround.hpp"

namespace dragon::cli {

// A first contact: {"time", "travel", "benches", "head_radius", "point", "tolerance"}.
Json contact_json(const Contact& c);
// collide's answer: the contact's keys (null where there is none), "evaluations", the window
// searched both ways ("from", "to", "from_travel", "to_travel"), "jam", then "handles" (every
// handle then, or null) if asked for.
Json collide_answer(const CollideAnswer& a, bool with_handles);
// {"pitch", "below_range", "above_range", "turn_radius", "search", "grid", "intervals", "jam",
// "guarantee"}; the jam, if any, has the pitch it was met at.
Json min_pitch_answer(const MinPitch& m, double turn_radius);
// The S-curve's design, whether this dragon can follow it, the first contact and the clearance
// up to it if the check was run ("first_contact": contact_json or null; "clearance": the
// smallest clearance before it, with the window searched), and the length study if given (the
// command's; a sweep leaves it out). "jam": where the valid motion ends on the check's window,
// else on the design.
Json turnaround_answer(const SCurve& design, const std::optional<Jam>& design_jam,
                       const std::optional<RunClearance>& clearance, const TurnaroundStudy* study);
// {"max_head_speed", "ratio", "unbounded", "handle", "time", "travel", "tied", "head_arc", "limit",
// "from", "to", "from_travel", "to_travel", "jam", "scan_step", "scan_travel", "candidates",
// "evaluations"}.
Json max_speed_answer(const MaxSpeed& m, double limit);

}  // namespace dragon::cli
