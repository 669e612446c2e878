// One step of the induction that carries a step of head travel down the chain link by link
// (docs/methods.md, sections 4.1 and 6.1): while the path from a link's rear handle's place at
// the step's start to its front handle's place at the step's end turns by less than pi/2, and
// the front handle stays on the arc between its own two places, the rear handle's root stays
// simple and the nearest behind the front, and the rear moves forward on the arc between its two
// places. Shared by the first contact's proof (swept_proof.cpp) and the valid motion's
// (motion_proof.cpp).
#pragma once

#include <numbers>

#include "dragon/path.hpp"

namespace dragon::gentle {

// rad: the largest turning of the path over a link's hull over a step for which the induction
// holds, pi/2 less a margin far above the rounding of Path::turning (~1e-15 rad).
inline constexpr double kMaxLinkTurning = 0.5 * std::numbers::pi - 1e-9;

// Whether place `a` is at or ahead of place `b` on the path (further in the direction of travel).
inline bool at_or_ahead(const Path& path, const Place& a, const Place& b) {
    if (a.piece != b.piece) return a.piece > b.piece;
    const auto [begin, end] = path.piece_span(a.piece);
    return end > begin ? a.u >= b.u : a.u <= b.u;
}

// The induction's step for one link, the front handle known to stay between its places at the
// step's two ends: its place at the end (`front_end`) is at or ahead of the rear handle's at the
// start (`rear_start`), and `hull_turning`, the path's turning from `rear_start` to `front_end`,
// is below kMaxLinkTurning. The caller checks that each handle ends at or ahead of where it began.
inline bool hull_turns_gently(const Path& path, const Place& front_end, const Place& rear_start, double hull_turning) {
    return at_or_ahead(path, front_end, rear_start) && hull_turning < kMaxLinkTurning;
}

}  // namespace dragon::gentle
