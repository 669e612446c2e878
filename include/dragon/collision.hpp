// Exact collision tests between bench rectangles, and the whole-dragon clearance.
#pragma once

#include <utility>
#include <vector>

#include "dragon/chain.hpp"
#include "dragon/geometry.hpp"

namespace dragon {

// Signed separation of two rectangles: the distance between them when apart (> 0), minus the
// penetration depth when they overlap (< 0), along `axis` (unit, pointing from a towards b).
// The distance is exact Euclidean distance when apart (corner-to-corner gaps included).
struct Separation {
    double distance;           // m: > 0 apart, < 0 overlapping
    Vec2 axis = Vec2::Zero();  // unit, from a towards b
    // A witness: the point of b nearest to a (apart), or the corner of either board deepest inside
    // the other (overlapping).
    Vec2 point = Vec2::Zero();
};
// How far apart boards a and b are, exactly (or how deep they overlap), and along which axis.
Separation separation(const Rect& a, const Rect& b);

// Where two touching (or nearly touching) boards meet, to mark it: the corner of either one
// nearest the other board. Boards touch corner to edge except in the measure-zero parallel
// case, where a corner is still a point of contact.
Vec2 contact_point(const Rect& a, const Rect& b);

// The smallest separation between two benches that do not share a handle.
// Benches are numbered 1..N; bench_a < bench_b. With fewer than 3 benches there is no such pair
// and distance is +infinity.
struct Clearance {
    double distance;            // m (+inf: no pair)
    int bench_a = 0;            // the nearer pair's first bench, 1..N
    int bench_b = 0;            // and its second, bench_a < bench_b
    Vec2 axis = Vec2::Zero();   // their Separation's axis
    Vec2 point = Vec2::Zero();  // their Separation's witness point
};

// Broad phase: every pair of non-adjacent benches whose rectangles might be within `margin` of
// each other (never misses one); pairs of bench numbers, first < second.
//
// A BroadPhase is its working memory, for a caller that asks again and again (a search, one per
// thread): the benches' order along x is kept between calls, so successive frames of a motion
// start nearly sorted and an insertion sort finishes it in about n steps, and no array is
// allocated once it has grown. The answer does not depend on what it held before.
class BroadPhase {
public:
    // The pairs, valid until the next call on this BroadPhase.
    const std::vector<std::pair<int, int>>& candidate_pairs(const Frame& f, double margin);

private:
    friend Clearance clearance(const Frame& f, double cutoff, BroadPhase& scratch);
    std::vector<std::pair<double, int>> order_;
    std::vector<double> lo_, hi_, x_, y_, rad_, gaps_;
    std::vector<int> index_;
    std::vector<std::pair<int, int>> pairs_;
};
// The broad phase's pairs (i, j), i < j, in one call.
std::vector<std::pair<int, int>> candidate_pairs(const Frame& f, double margin);

// Clearance over all non-adjacent pairs, through the broad phase. Pairs farther apart than
// `cutoff` may be reported as cutoff (only the minimum matters).
Clearance clearance(const Frame& f, double cutoff = 1e300);
Clearance clearance(const Frame& f, double cutoff, BroadPhase& scratch);

// Reference: clearance by checking every pair (for tests and the broad phase's proof).
Clearance clearance_all_pairs(const Frame& f);

// Two non-adjacent benches overlapping: past the first contact the chain lies across itself.
struct Overlap {
    int bench_a = 0;               // 1..N
    int bench_b = 0;               // 1..N, bench_a < bench_b
    double depth = 0.0;            // penetration depth, m (> 0)
    Vec2 point = Vec2::Zero();     // the corner of either board deepest inside the other
};
// Every overlapping pair of the frame (through the broad phase), deepest first.
std::vector<Overlap> overlaps(const Frame& f);

}  // namespace dragon
