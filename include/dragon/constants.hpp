// Named tolerances and limits, each with its unit and the reason for its value.
#pragma once

#include <numbers>

namespace dragon {

// One turn, rad.
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The broad phase of the searches' collision checks: pairs of benches whose bounding circles come
// within this of each other are tested exactly (and bounded pair by pair); the others are bounded
// group by group, m. The gallery's fig3 draws it.
inline constexpr double kBroadPhaseMargin = 0.7;

}  // namespace dragon

namespace dragon::tol {

// Root finders on a path parameter stop when a Newton step is below this (radians of theta or of
// arc angle). Newton converges quadratically, so the error after such a step is ~1e-16 rad:
// positions good to ~1e-14 m on a 10 m spiral, far below the 6 printed decimals.
inline constexpr double newton_step = 1e-9;

// Halley's method (cubic convergence) stops after a step below this (radians): the error left
// is of order step^3 ~ 1e-18 rad.
inline constexpr double halley_step = 1e-6;

// Relative tolerance for inverting arc length (dimensionless): 1e-15 of a ~450 m spiral is
// still sub-picometre.
inline constexpr double arc_relative = 1e-15;

// Iteration caps: every root finder here converges in a handful of steps; the caps only turn a
// bug into an error instead of a hang.
inline constexpr int max_newton = 60;
inline constexpr int max_march = 400;

// Searches that step by a bound on how fast a margin can shrink (first contact, the end of the
// valid motion, the turnaround's clearance scan, max-speed's refinement) assume the true rate
// over a step stays below this many times the rate measured at its start; every accepted
// step's assumption is checked at its end (the rate there, and what the margin did), and a
// step whose check fails is taken again shorter. The benches' velocities change by far less over one step of at most 2 m of head
// travel.
inline constexpr double rate_safety = 2.0;

// Slacks of those end-of-step checks (they choose steps; docs/methods.md says which proofs
// stand on them). A promise "this bound holds over the step" is kept when the value found at
// the step's end is within `promise_relative` of it (dimensionless), so that rounding in the
// rates and gaps (relative ~1e-15) never sends a step back: a bound broken by less than 1e-9 of
// itself is not a bound the step relied on.
inline constexpr double promise_relative = 1e-9;
// m/m of head travel: the same for a change of a corner gap's rate that should be 0 (rates of
// ~1 m/m rounded to ~1e-16 each; 1e-12 is 1e4 roundings).
inline constexpr double promise_rate_change = 1e-12;
// m: the same for a margin of the valid-motion walk (margins of ~1 m rounded to ~1e-16).
inline constexpr double promise_margin = 1e-15;
// m: the same for a handle's move over a step of the valid-motion walk (positions of ~10 m
// computed to ~1e-14 m, at each of the step's two ends).
inline constexpr double promise_move = 1e-12;

// Head travel to which events in time (a first contact, the end of the valid motion) are
// located, m. The chain's shape depends on the head's travel alone, so the searches run in
// travel and find the same event, bit for bit, at any head speed; as time this is
// travel / speed: 1e-11 s at the contest's 1 m/s, and within the 1e-9 s that answers print for
// any head speed down to 1 cm/s. (Rounding in the chain moves a contact by ~1e-13 m of travel.)
inline constexpr double travel = 1e-11;
// Pitch to which the minimum pitch is refined, m (the issue asks for 1e-8 m; ten times finer).
inline constexpr double pitch = 1e-9;

}  // namespace dragon::tol
