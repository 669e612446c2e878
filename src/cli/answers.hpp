// The --json answers of the question commands (collide, min-pitch, turnaround, max-speed), built
// in one place: the commands print them and dragon sweep writes them into its rows, so that a
// sweep's row holds exactly what the single command answers for that scenario.
#pragma once

#include <optional>

#include "cli/report.hpp"
#include "dragon/analyses.hpp"
#include "dragon/turnaround.hpp"

namespace dragon::cli {

// Q2's search as collide runs it: from `from` up to `to`, or without `to` as far as the dragon
// can follow its path. Throws InputError naming --from or --to for a range it cannot search.
struct CollideSearch {
    std::optional<Contact> contact;
    double from = 0.0, to = 0.0;
    // The end of the valid motion, when it cut the range short and nothing touched before it.
    std::optional<Jam> jam;
};
// Throws InputError naming --from or --to unless they are finite and in order (search_collision
// checks them too; a command calls it first to check them before anything else).
void check_collide_range(double from, std::optional<double> to);
CollideSearch search_collision(const Simulation& sim, double from, std::optional<double> to,
                               Executor* executor = nullptr);

// {"time", "benches", "head_radius", "point", "tolerance", "evaluations", "from", "to", "jam"}
// (null where there is no contact), then "handles" (every handle then, or null) if asked for.
Json collide_answer(const CollideSearch& search, bool with_handles);
// {"pitch", "below_range", "above_range", "turn_radius", "search", "grid", "intervals", "jam",
// "guarantee"}; the jam, if any, has the pitch it was met at.
Json min_pitch_answer(const MinPitch& m, double turn_radius);
// The S-curve's design, whether this dragon can follow it, the clearance check if it was run,
// and the length study if given (the command's; a sweep leaves it out). "jam": where the valid
// motion ends on the clearance check's range, else on the design.
Json turnaround_answer(const SCurve& design, const std::optional<Jam>& design_jam,
                       const std::optional<RunClearance>& clearance, const TurnaroundStudy* study);
// {"max_head_speed", "ratio", "unbounded", "handle", "time", "tied", "head_arc", "limit", "from",
// "to", "jam", "scan_step", "candidates", "evaluations"}.
Json max_speed_answer(const MaxSpeed& m, double limit);

}  // namespace dragon::cli
