// Bounds on how sharply each handle's path bends in head travel over a step: for handle k at
// P_k(x) (x: the head's travel), a bound on |P_k''(x)| that holds at every x of the step, from the
// chain at the step's two ends alone (docs/methods.md, section 6.1, Proposition 7).
//
// Along the path each handle moves at v_k = d sigma_k / dx (its speed per unit of head speed), so
// P_k'' = v_k' T_k + v_k^2 kappa_k N_k and |P_k''| = hypot(v_k', v_k^2 kappa_k). The rigid link
// from handle k to k + 1 (u: the unit vector from the rear to the front, n = perp(u); phi_F and
// phi_R the angles from u to the tangents at the front and at the rear) gives
//     v_{k+1} = v_k rho,  rho = cos(phi_F) / cos(phi_R),
// and, differentiating along the front's arc sigma (the link turns at w = (sin phi_F - rho
// sin phi_R) / d, its ends' tangents at kappa_F and rho kappa_R),
//     d rho / d sigma = [sin phi_F (w - kappa_F) cos phi_R - cos phi_F sin phi_R (w - rho kappa_R)]
//                       / cos^2 phi_R,
// which is 0 on a circle (phi_R = -phi_F, w = kappa): its terms are kept signed and evaluated on
// intervals, so the bound is as small as the shape's change over the step, not as the
// curvature. Then v_{k+1}' = v_k' rho + v_k^2 (d rho / d sigma): from the head (v_0 = 1,
// v_0' = 0) the bounds go down the chain link by link, each v_k anchored on its exact values at
// the step's two ends (v_k(x) <= max(v_k(x0), v_k(x1)) + h max|v_k'| / 2).
//
// The angles over the step lie between their end values widened by what they can turn: phi_F
// changes at kappa_F - w and phi_R at rho kappa_R - w per unit of sigma, with |w| bounded from
// the link's hull turning tau (|phi| <= tau, rho <= 1 / cos(tau)), then once more from the
// intervals of w and rho that gives. Curvatures come from each
// handle's arc over the step (|kappa| monotone on each piece of the path, methods.md 10.1).
//
// Assumes what prove_step's first part proves: every handle moves forward over the step (its arc
// is the one between its end places) and every link's hull turns by less than pi/2.
#pragma once

#include <vector>

#include "dragon/chain.hpp"
#include "dragon/path.hpp"
#include "dragon/scenario.hpp"

namespace dragon::contact {

// Fills accel[k] (k = 0..N) with the bound on |P_k''| (1/m) over head travel between the frames
// f0 and f1 (f0 earlier; both with every handle's exact speed), and speed[k] with the bound on
// |P_k'| = v_k. hull_turning[k]: the path's
// turning over link k's hull, from handle k + 1's place in f0 to handle k's in f1; own_turning[k]:
// over handle k's own arc, from its place in f0 to its place in f1. False (accel
// left partial) where no bound is made: a link's hull turning pi/2 or more, a head standing still.
bool handle_accel_bounds(const Path& path, const BenchSpec& spec, const Frame& f0, const Frame& f1,
                         const std::vector<double>& hull_turning, const std::vector<double>& own_turning,
                         std::vector<double>& accel, std::vector<double>& speed);

}  // namespace dragon::contact
