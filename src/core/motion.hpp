// Rigid-body velocity fields of the benches, for bounding how fast separations can change.
#pragma once

#include <vector>

#include "dragon/chain.hpp"

namespace dragon {

// v(x) = v_centre + omega * perp(x - centre) for every point x of the bench.
struct BenchMotion {
    Vec2 centre = Vec2::Zero();
    Vec2 v_centre = Vec2::Zero();
    double omega;
    Vec2 at(const Vec2& x) const { return v_centre + omega * perp(x - centre); }
};

// From the handles' exact velocities (speed times unit tangent). Rigidity makes both ends'
// velocity components along the bench equal, so the across-components give the turn rate.
std::vector<BenchMotion> bench_motions(const Frame& f);
// The same into `out`, reusing its storage.
void bench_motions_into(const Frame& f, std::vector<BenchMotion>& out);

// An upper bound on |d/dt separation(a, b)| now: the largest speed of a point of a relative to
// the body of b. The relative velocity field is affine, so its largest norm over a rectangle is
// at a corner; moving from a's witness to b's adds at most |omega_b| times the gap.
double separation_rate_bound(const Rect& a, const BenchMotion& ma, const BenchMotion& mb, double gap);

// The bench's distances from the origin and a bound on how fast any of them changes. A point x
// of the bench moves at (v_centre - omega perp(centre)) + omega perp(x), and perp(x) is square
// to x, so |x| changes at most at |v_centre - omega perp(centre)|: small while the chain turns
// about the origin almost rigidly, as it does on the spiral.
struct Radial {
    double lo, hi;  // the bench's points lie at distances [lo, hi] from the origin
    double speed;   // |d|x|/dt| <= speed for every point x of the bench
};
Radial radial_extent(const Rect& r, const BenchMotion& m);

// The largest speed of any point of the bench now.
double max_point_speed(const Rect& r, const BenchMotion& m);

}  // namespace dragon
