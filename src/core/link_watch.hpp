// One link of the chain watched for the end of the valid motion (see dragon/valid_motion.hpp):
// how far it is from losing its rear handle's root, and for how much head travel that margin
// is sure to last.
#pragma once

#include <cmath>
#include <optional>

#include "dragon/chain.hpp"
#include "dragon/constants.hpp"
#include "dragon/path.hpp"

namespace dragon::jam {

// Steps assume the margin's rate of change grows by at most this factor over the step (the
// contact search's assumption too); the next evaluation checks it.
inline constexpr double kSafety = tol::rate_safety;
// Links whose path turns by less than this between their handles are certified by that turning
// alone (pi/2 is the limit: below it the distance from the front handle grows all along the
// link), rad. Above it, the health is computed.
inline constexpr double kGentleTurn = 1.2;
// Head travel per step at most, m: keeps the rates the steps assume close to the ones measured
// (the first-contact search uses the same cap).
inline constexpr double kMaxStep = 2.0;
inline constexpr double kQuarterTurn = 1.5707963267948966192313216916398;

// A link at one moment. Speeds are per unit head speed (the chain solved with the head at 1 m/s).
struct LinkCheck {
    bool calm = false;  // wholly on calm path (below); margin 1, turn 0
    double turn = 0.0;  // the path's turning between the handles, rad
    bool gentle = true;
    // Gentle: quarter turn minus the turning between the handles, rad. Otherwise the health, m.
    double margin = 0.0;
    // Head travel over which the margin stays positive, m (it may fall by margin * travel /
    // step at most, kSafety times its current rate).
    double step = 0.0;
    // Not gentle: the arc position where the health is least (the tangency to watch), and whether
    // that is the rear handle itself (its root about to vanish) rather than a point between.
    double watch_arc = 0.0;
    bool at_root = false;
};

// Stretches of path where the curvature k satisfies k d <= kCalmBend for a link of length d
// are certified without a look: a link there spans at most 2 asin(kCalmBend / 2) = 1.42 rad <
// pi/2 of turning (Schur's comparison theorem: its chord is at least that of a circle of
// curvature k), a margin of 0.15 rad kept against rounding.
inline constexpr double kCalmBend = 1.3;

// Where the path is calm for a link of length d (Path::curvature_bounded_before/after with
// k = kCalmBend / d): a link whose front is at or behind `before`, or whose rear is at or ahead
// of `after`, lies wholly on calm path.
struct Calm {
    double before = -INFINITY;
    double after = INFINITY;
};
Calm calm_for(const Path& path, double chord);

// `front`, `rear`: the link's handles (rear = the chord root behind front), chord: its length,
// dir: +1 when the head moves ahead, -1 when it moves back (the handles' speeds are per unit of
// head travel ahead).
LinkCheck check_link(const Path& path, const Handle& front, const Handle& rear, double chord, const Calm& calm,
                     double dir);

// The local maximum of the distance R(s') = |P(s') - q| over the path nearest the arc position
// `seed` (within `window` of it), and how far it reaches past the chord: excess = R - chord.
// A jam is this excess crossing zero. dir: unit vector from q to that point.
struct Tangency {
    double arc = 0.0;
    double excess = 0.0;
    Vec2 point = Vec2::Zero();
    Vec2 dir = Vec2::Zero();
};
std::optional<Tangency> watch_tangency(const Path& path, const Vec2& q, double chord, double seed, double window);

}  // namespace dragon::jam
