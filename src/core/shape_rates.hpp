// Bounds on how fast and how sharply each handle moves in the frame turned with the head, as the
// head's radius r0 changes at a fixed pitch, over a cell of head radii and pitches on the plain
// spiral r = b theta (docs/methods.md, section 8.1, Proposition P5).
//
// In that frame handle m lies at P_m = rho_m (cos D_m, sin D_m), rho_m = r0 + b D_m its radius
// and D_m its polar offset from the head; the chain's common turning, which sets the fixed
// frame's accelerations, is gone and only the change of the chain's shape is left. Each link's
// span alpha_m = D_{m+1} - D_m is the nearest root A(rho_m, b) of
//     F(alpha; rho, b) = rho^2 + (rho + b alpha)^2 - 2 rho (rho + b alpha) cos(alpha) - d^2 = 0,
// so, with ' = d/dr0 at fixed b, A_rho = -F_rho / F_alpha and
// A_rhorho = -(F_rhorho + 2 F_rhoalpha A_rho + F_alphaalpha A_rho^2) / F_alpha, and from the head
// (D_0 = 0, rho_0' = 1):
//     D_{m+1}'  = D_m' (1 + b A_rho) + A_rho,
//     D_{m+1}'' = D_m'' (1 + b A_rho) + A_rhorho (1 + b D_m')^2,
//     P' = rho' e + rho D' e_perp,  P'' = (b D'' - rho D'^2) e + (2 rho' D' + rho D'') e_perp.
// Everything is evaluated on intervals that hold over the whole cell: each link's rho_m and
// alpha_m lie between their values in the chain at (r0_hi, b_hi) and in the chain at
// (r0_lo, b_lo) (Proposition P2, pitch_proof.hpp, under the conditions the caller checks there),
// and b in [b_lo, b_hi]. Where alpha < pi/2 every term of F_alpha is positive, so the division is
// safe; a span at pi/2 or more gives no bound.
#pragma once

#include <vector>

#include "dragon/chain.hpp"

namespace dragon::contact {

// Fills speed[m] and accel[m] (m = 0..N, the handles both frames hold) with bounds on |P_m'| and
// |P_m''| (per m and per m of head radius) over the cell whose chains with the least polar
// offsets (`least`: the largest head radius and b) and the largest (`most`: the least of both)
// are given, b in [b_lo, b_hi] (m/rad). False (the vectors left partial) where a link's span in
// `most` is pi/2 or more, or one in `least` is not positive.
bool shape_rate_bounds(const Frame& least, const Frame& most, double b_lo, double b_hi, std::vector<double>& speed,
                       std::vector<double>& accel);

}  // namespace dragon::contact
