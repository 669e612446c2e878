// Which benches a contact search must watch: on the plain spiral, the benches far out on the
// chain stay on their own turn of the spiral, a pitch away from the next one, and cannot touch
// anything while the head coils in over a stretch of time. Proving that for the tail lets the
// search solve and test only the benches ahead of it (about an eighth of the contest's chain).
//
// The certificate, for a stretch [first.time, last.time] of motion on the spiral r = b theta:
//  - every handle's theta falls over the stretch and each link's angle grows (checked: each
//    link at the last frame spans less than a quarter turn and theta_k > tan(angle / 2), which
//    makes d theta_{k+1} / d theta_k > 0 and the angle a falling function of theta_k there and
//    everywhere farther out); so the last frame bounds every bench's radius from below;
//  - every point of bench i, written in polar form with its angle psi unwrapped continuously
//    from the bench's handles, lies within [-in_i, out_i] of the spiral (rho - b psi) and within
//    alpha_i of the handles' angles. The chord dips inside the spiral between the holes (by at
//    most M d^2 / 8, M a bound on the curvature of rho - b psi along the chord's line) and the
//    board's ends stand outside it (by at most M o (d + o) / 2); the width adds at most
//    hw |grad(rho - b psi)|;
//  - benches i < j share a point only if its two unwrapped angles differ by 2 pi m, so that
//    p m lies within [-(in_i + out_j), out_i + in_j], and the benches' angle spans, one shifted
//    by 2 pi m, overlap at that moment. Spans only separate as the chain coils in: the gap
//    theta_{j-1} - theta_i is smallest at the first frame, theta_j - theta_{i-1} largest at the
//    last.
// A pair that none of these rules out keeps both benches watched. Anything the argument needs
// and does not find (another path, a bench too near the centre, a pitch the offsets fill many
// times over) watches the whole chain.
#pragma once

#include <optional>
#include <vector>

#include "dragon/chain.hpp"

namespace dragon {

class Spiral;

// How far bench `bench`'s board can stray from the spiral r = b theta over a stretch: every
// point's offset rho - b psi lies within [-in, out], and its angle psi (unwrapped from the
// handles') within `angle` of the handles' span. From its handles' angles at the last frame
// (the least radii) and its link's angle at the first frame (the least). nullopt when the board
// comes so near the centre that the bounds do not hold.
struct BenchReach {
    double in, out, angle;
};
std::optional<BenchReach> bench_reach(double b, const BenchSpec& spec, int bench, double front_last, double rear_last,
                                      double span_first);

// The number K of leading benches (1..K) outside of which no two non-adjacent benches can
// touch at any moment between the two frames of motion on `spiral` (first.time <= last.time):
// every pair with a bench numbered above K stays apart. spec.bench_count when nothing is proved.
int benches_that_may_touch(const Spiral& spiral, const BenchSpec& spec, const Frame& first, const Frame& last);

// All the proof reads of a frame: its time and its handles' angles on the spiral (a search keeps
// these for the edges of its stretches, a fortieth of the whole frames' memory).
struct ChainAngles {
    double time = 0.0;
    std::vector<double> theta;  // every handle's place.u, head front first
    bool on_spiral = true;      // every handle on the spiral's one piece
};
ChainAngles chain_angles(const Frame& f);
int benches_that_may_touch(const Spiral& spiral, const BenchSpec& spec, const ChainAngles& first,
                           const ChainAngles& last);

}  // namespace dragon
