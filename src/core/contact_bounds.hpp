// Bounds on how fast benches far apart can close in, for the first-contact search's steps.
#pragma once

#include <vector>

#include "contact_step.hpp"
#include "motion.hpp"
#include "dragon/chain.hpp"
#include "dragon/constants.hpp"

namespace dragon::contact {

// The slack on the closing-speed bounds over one step is the search's (Workspace::rate_safety,
// by default tol::rate_safety): it chooses the steps' lengths; the steps' proof does not use it.

// The benches' distances from the origin and how fast they change (motion.hpp), for every bench.
void radial_extents(const Frame& f, const std::vector<BenchMotion>& motion, std::vector<Radial>& out);
// A lower bound on the distance between two benches, or two groups, from their radii alone
// (not positive when their radii overlap), and the head travel (m) that distance lasts at least.
double radial_gap(const Radial& a, const Radial& b);
double radial_step(const Radial& a, const Radial& b, double rate_safety);

// The head travel (m) over which no pair of benches farther apart than `margin` can touch (see
// contact_bounds.cpp). Each group pair's bounds go to `record`. Given `last`, the records of the
// evaluation `step` m of head travel back (the same groups), `broken` is set when a group pair closes here faster than the gap it
// had there could take for the whole step: the step's promise for it did not hold at its end.
double far_pairs_step(const Frame& f, const std::vector<BenchMotion>& motion, const std::vector<double>& half_diagonals,
                      const std::vector<Radial>& radial, double margin, std::vector<GroupRecord>& record,
                      double rate_safety, const std::vector<GroupRecord>* last = nullptr, double step = 0.0,
                      bool* broken = nullptr);

}  // namespace dragon::contact
