// The minimum pitch's intervals proved pitch by pitch (MinPitchOptions::prove; docs/methods.md,
// section 8.1): every pitch inside the feasible ones, not only the grid's and the narrowing's,
// reaches the turning space's boundary with no two benches touching; every pitch inside the
// others meets a contact before it.
//
// The proof covers cells of (head radius r0, spiral parameter b = pitch / 2 pi). On the plain
// spiral r = b theta let a link's front handle be at radius rho and its rear handle alpha
// further round: F(alpha; rho, b) = rho^2 + (rho + b alpha)^2 - 2 rho (rho + b alpha) cos alpha
// - d^2 = 0. On (0, pi], F rises in alpha, rho and b (its three partial derivatives are
// positive there), so the nearest root alpha = A(rho, b) is simple and falls in rho and in b.
// The rear's radius G(rho, b) = rho + b A(rho, b) rises in b, and in rho where
// rho > b tan(alpha / 2) and alpha <= pi / 2. Along the chain from the head (rho_0 = r0) every
// handle's radius then rises, and every link's span and every polar offset D_i from the head
// falls, in r0 and in b: over the cell [r0_lo, r0_hi] x [b_lo, b_hi] each lies between its
// values in the chain at (r0_hi, b_hi) and the chain at (r0_lo, b_lo), checked there (the
// conditions at the corner where the spans are largest and the radii least hold everywhere).
// Handle i lies at (r0 + b D_i) (cos D_i, sin D_i) in the frame turned with the head: linear in
// (r0, b) for fixed D, so swept_proof's enclosures at the cell's four corners prove the whole
// cell (prove_spiral_cell: first order in the cell's size). Tried first, the second order in
// r0 (prove_spiral_cell_second_order): the benches enclosed over the range of b at each of the
// two radii, and between them each corner within h^2 / 8 of its chord in that frame
// (shape_rates.hpp bounds its second derivative in r0 there). Every pitch in [b_lo, b_hi] 2 pi
// starts no farther out than r0 = 2 pi b_hi start_turn: cells from there in to the turning
// space's radius cover its run.
#pragma once

#include <vector>

#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"
#include "dragon/executor.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

// m: a feasible range of pitches no wider than this that its cells cannot prove is left
// unproved (the pitches next to a change of feasibility, where a pair's closest approach falls
// to zero): the search's own resolution of the cut (tol::pitch; a colliding range is halved
// finer, up to that resolution from the cut, pitch_proof.cpp's kCollidingFinest). Each
// feasible interval's least pitch, the search's answer, is marched on its own as well (a range
// of one pitch, whose cells are steps of that dragon's motion in).
inline constexpr double kPitchProofFinest = tol::pitch;

// Proves the intervals of `intervals` (min_pitch's) each as it says, feasible or colliding, each
// range of pitches on its own; the scenario's bench, start_turn and turn_radius are the runs'.
// A colliding range is proved by a witness: at one head radius r at or outside the turning
// space and inside every pitch's start (so on every pitch's run), a corner of one bench of a
// pair lies inside the other at the range's middle pitch deeper than both can move over the
// range (Proposition P2 at the fixed radius r bounds every handle's polar offset between its
// values at the range's ends; each handle then moves at most
// D |b - b_mid| + sqrt(b^2 + (r + b D)^2) |D - D_mid|, and a corner as its two handles do).
// Every pitch of the range then overlaps at r: it met its first contact before the boundary.
// The witness (a pair and a radius) is looked for, cheapest first: the parent range's, that pair
// again at the radius where it overlaps most at this range's middle pitch, the whole chain's
// deepest overlaps at a few radii, and last the middle pitch's run (its first contact's pair);
// which one is found decides only how many ranges are halved, never what is proved.
PitchProof prove_pitches(const Scenario& s, const std::vector<PitchInterval>& intervals, Executor& ex);

}  // namespace dragon
