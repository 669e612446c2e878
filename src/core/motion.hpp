// Rigid-body velocity fields of the benches, for bounding how fast separations can change.
#pragma once

#include <vector>

#include "dragon/chain.hpp"

namespace dragon {

// v(x) = v_centre + omega * perp(x - centre) for every point x of the bench.
struct BenchMotion {
    Vec2 centre;
    Vec2 v_centre;
    double omega;
    Vec2 at(Vec2 x) const { return v_centre + omega * perp(x - centre); }
};

// From the handles' exact velocities (speed times unit tangent). Rigidity makes both ends'
// velocity components along the bench equal, so the across-components give the turn rate.
std::vector<BenchMotion> bench_motions(const Frame& f);

// An upper bound on |d/dt separation(a, b)| now: the largest speed of a point of a relative to
// the body of b. The relative velocity field is affine, so its largest norm over a rectangle is
// at a corner; moving from a's witness to b's adds at most |omega_b| times the gap.
double separation_rate_bound(const Rect& a, const BenchMotion& ma, const BenchMotion& mb, double gap);

// The largest speed of any point of the bench now.
double max_point_speed(const Rect& r, const BenchMotion& m);

}  // namespace dragon
