// The distance between two disjoint rectangles is the smallest of eight smooth functions: each
// corner's distance to the other rectangle (the closest pair of two disjoint convex polygons
// always involves a corner). Each has an exact rate from the benches' rigid velocity fields, so
// near a contact the stepper can bound each one to second order instead of bounding their
// minimum, which is not smooth when the closest corner changes.
#pragma once

#include <array>

#include "motion.hpp"
#include "dragon/geometry.hpp"

namespace dragon {

struct CornerGap {
    double distance;  // from the corner to the other rectangle (0 when inside)
    double rate;      // d/dt of that distance now (envelope theorem: the nearest point's slide
                      // along the boundary does not change it to first order)
};

// Corners of a against b (entries 0..3), then corners of b against a (4..7).
std::array<CornerGap, 8> corner_gaps(const Rect& a, const BenchMotion& ma, const Rect& b, const BenchMotion& mb);

// The longest time h for which d + rate h - curvature h^2 / 2 stays positive: a function with
// this value and rate now and |second derivative| <= curvature cannot reach zero sooner.
double second_order_step(double distance, double rate, double curvature);

}  // namespace dragon
