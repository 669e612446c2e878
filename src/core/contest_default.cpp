#include "dragon/scenario.hpp"

namespace dragon {

// Exact comparisons: flags, files and the defaults parse the same decimal to the same double.
bool is_contest_default(const Scenario& s) {
    const Scenario d;
    const BenchSpec &a = s.bench, &b = d.bench;
    const PathSpec &p = s.path, &q = d.path;
    return a.bench_count == b.bench_count && a.head_length == b.head_length && a.body_length == b.body_length &&
           a.width == b.width && a.hole_offset == b.hole_offset && p.pitch == q.pitch &&
           p.start_turn == q.start_turn && p.turn_radius == q.turn_radius && p.turn_pitch == q.turn_pitch &&
           p.arc_ratio == q.arc_ratio && s.head_speed == d.head_speed;
}

}  // namespace dragon
