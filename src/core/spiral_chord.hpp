// One link of a chain out along the plain spiral, where the chord cannot reach round past the
// far side of the centre (Spiral::behind's common case): Halley's method on the angle the link
// spans, started from what the last link learned (ChordMemo). Inline, so that a loop over a whole
// chain (solve_chain_front) keeps each link's state in registers: through the virtual
// Path::behind, which returns through memory, each link waits on the stores and loads of the last.
#pragma once

#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "dragon/constants.hpp"
#include "dragon/path.hpp"
#include "dragon/portable_math.hpp"

namespace dragon::spiral_chord {

inline constexpr double kPi = std::numbers::pi;

// With phi = theta' - theta, the squared chord over b^2 is
//   g(phi) = theta^2 + (theta + phi)^2 - 2 theta (theta + phi) cos(phi),
//   g'(phi) = 2 [(theta + phi) - theta cos(phi) + theta (theta + phi) sin(phi)] > 0 on (0, pi],
// so when g(pi) = (2 theta + pi)^2 >= (chord / b)^2 there is exactly one root in (0, pi]: the
// nearest one, found here. Otherwise the chord may reach round past the far side.
inline bool within_half_turn(double b, double theta, double chord) { return !(2.0 * theta + kPi < chord / b); }

// A memo's drift larger than this (rad) is no guess worth taking: the circle model starts instead.
inline constexpr double kMemoDrift = 0.1;
// Below this argument asin's series (four terms, relative error under 2e-5) is first guess enough.
inline constexpr double kAsinSeries = 0.5;
// Halley steps below this (rad) move the half angle's cos and sin by the angle-sum rule with the
// step's series (|step / 2| <= 5e-4: the dropped terms are below 1e-22) instead of a sincos.
inline constexpr double kSeriesStep = 1e-3;

// cos and sin of d from their series: |d| <= 0.05 leaves the dropped terms below 1e-20.
inline std::pair<double, double> cos_sin_small(double d) {
    const double d2 = d * d;
    return {1.0 - d2 * (0.5 - d2 * (1.0 / 24.0 - d2 * (1.0 / 720.0 - d2 * (1.0 / 40320.0)))),
            d * (1.0 - d2 * (1.0 / 6.0 - d2 * (1.0 / 120.0 - d2 * (1.0 / 5040.0 - d2 * (1.0 / 362880.0)))))};
}

// Where Halley's method starts: the angle, and the cos and sin of its half when known already.
struct FirstGuess {
    double phi;
    double cos_half = 1.0, sin_half = 0.0;
    bool have_half = false;
};

inline FirstGuess first_guess(const ChordMemo& memo, double th, double chord, double k) {
    if (memo.theta == th && memo.chord == chord && std::abs(memo.drift) <= kMemoDrift && memo.angle + memo.drift > 0.0 &&
        memo.angle + memo.drift < kPi) {
        // The last link of this length, one handle nearer the head, spanned memo.angle; the
        // angle changes smoothly along the spiral, and memo.drift is its first-order change
        // (relative error 4e-6 far out to 1e-3 near the centre, against the circle model's 1e-3
        // to 1.5e-2 below). The half angle's cos and sin follow by the angle-sum rule with the
        // drift's series, so no sincos.
        const auto [cd, sd] = cos_sin_small(0.5 * memo.drift);
        return {memo.angle + memo.drift, memo.cos_half * cd - memo.sin_half * sd, memo.sin_half * cd + memo.cos_half * sd,
                true};
    }
    // The circle approximation: a chord k at radius ~theta subtends 2 asin(k / 2 theta). Only a
    // first guess: where the argument is small, a few terms of asin's series spare the libm call.
    const double x = k / (2.0 * std::sqrt(th * th + 1.0));
    if (x <= kAsinSeries) {
        const double x2 = x * x;
        return {2.0 * x * (1.0 + x2 * (1.0 / 6.0 + x2 * (3.0 / 40.0 + x2 * (5.0 / 112.0))))};
    }
    return {x < 1.0 ? 2.0 * math::asin(x) : 0.5 * kPi};
}

// Halley's result: the angle, the last step, and at the start of that step (began) the cos and
// sin of the angle (c, s) and of its half (ch, sh), and g's derivatives in the angle (g_phi) and
// in theta (g_theta = 2 (2 theta + phi)(1 - cos phi)).
struct HalleyRoot {
    double phi, step, began;
    double c, s, ch, sh;
    double g_phi, g_theta;
};

// Halley's method (cubic convergence) with a bisection fallback on (0, pi]. g' and g'' reuse the
// same cos and sin, so each iteration costs one sincos. g is summed as
//   g(phi) = phi^2 + 2 theta (theta + phi) (1 - cos phi),
// two positive terms: the textbook form theta^2 + (theta + phi)^2 - 2 theta (theta + phi) cos phi
// cancels theta^2 against itself, which far out on the spiral (a link of 1 m at radius 70 km:
// phi ~ 1e-5, theta ~ 1e4) left chords wrong by 1e-6 relative (found by tests/fuzz/fuzz_chain).
// The step is judged relative to phi for the same reason: a root of 1e-5 rad is not found
// to 1e-6 rad.
inline HalleyRoot halley(double th, double k2, FirstGuess guess) {
    double lo = 0.0, hi = kPi;
    double phi = guess.phi, c = 1.0, s = 0.0, step = 0.0;
    double ch = guess.cos_half, sh = guess.sin_half;
    double dg = 0.0, g_theta = 0.0, began = phi;
    for (int it = 0; it < tol::max_newton; ++it) {
        const double t2 = th + phi;
        // From the half angle: 1 - cos phi = 2 sin^2(phi / 2) has no cancellation and no division.
        // After a small step, the half angle's cos and sin follow from the last ones by the
        // angle-sum rule with the step's Taylor series, saving a sincos on the second iteration,
        // which is usually the last.
        if (it == 0 && guess.have_half) {
            // from the memo
        } else if (it > 0 && std::abs(step) <= kSeriesStep) {
            const double d = 0.5 * step, d2 = d * d;
            const double cd = 1.0 - d2 * (0.5 - d2 * (1.0 / 24.0 - d2 * (1.0 / 720.0)));
            const double sd = d * (1.0 - d2 * (1.0 / 6.0 - d2 * (1.0 / 120.0)));
            const double ch_next = ch * cd - sh * sd;
            sh = sh * cd + ch * sd;
            ch = ch_next;
        } else {
            ch = math::cos(0.5 * phi);
            sh = math::sin(0.5 * phi);
        }
        const double one_minus_c = 2.0 * sh * sh;
        c = 1.0 - one_minus_c;
        s = 2.0 * sh * ch;
        const double g = phi * phi + 2.0 * th * t2 * one_minus_c - k2;
        if (g < 0.0) lo = phi; else hi = phi;
        began = phi;
        dg = 2.0 * (phi + th * one_minus_c + th * t2 * s);
        g_theta = 2.0 * (th + t2) * one_minus_c;
        const double ddg = 2.0 * (1.0 + 2.0 * th * s + th * t2 * c);
        double next = phi - 2.0 * g * dg / (2.0 * dg * dg - g * ddg);
        // Closed bracket: at (or a rounding step from) the root, phi itself is an end of it.
        if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
        step = next - phi;
        phi = next;
        if (std::abs(step) <= tol::halley_step * phi || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * (th + kPi)) break;
    }
    return {phi, step, began, c, s, ch, sh, dg, g_theta};
}

// A handle as the next link's solve needs it: its angle, position and memo. Plain numbers, so
// that a loop carrying it from link to link keeps it in registers.
struct Link {
    double theta, x, y;
    ChordMemo memo;
};

// The handle behind `l` at the chord, given within_half_turn(b, l.theta, chord): `l` becomes it
// and (tx, ty) its tangent. Returns false instead, leaving `l` as it was, where the short cuts
// below do not apply (near the centre, or Halley's last step large): the handle is then
// spiral.at({0, theta2}), with no memo.
inline bool next_link(double b, double chord, Link& l, double& tx, double& ty, double& theta2) {
    const double th = l.theta;
    const double k = chord / b;
    const HalleyRoot h = halley(th, k * k, first_guess(l.memo, th, chord, k));
    const double phi = h.phi, step = h.step;
    const double th2 = th + phi;
    theta2 = th2;
    if (th < 1.0 || std::abs(step) > tol::halley_step * phi) return false;
    // cos and sin of the last step's end from those of its start (|step| <= 1e-6 phi, so the
    // dropped terms are below 1e-18), then of theta' = theta + phi by the angle-sum rule, with cos and
    // sin of theta read off the previous handle's position: one sincos per handle saved.
    const double cp = h.c * (1.0 - 0.5 * step * step) - h.s * step;
    const double sp = h.s * (1.0 - 0.5 * step * step) + h.c * step;
    const double r0 = b * th;
    const double c0 = l.x / r0, s0 = l.y / r0;
    const double c2 = c0 * cp - s0 * sp, s2 = s0 * cp + c0 * sp;
    const double r2 = b * th2;
    const double inv = 1.0 / std::sqrt(1.0 + th2 * th2);
    // The memo for the next link: the half angle's cos and sin moved by the last step like cp and
    // sp above, and the angle's change to the next link: phi * dphi/dtheta, dphi/dtheta =
    // -g_theta / g_phi, plus the second-order term from the change of that slope since the last
    // link, which leaves the next guess within 1e-6 of its root on most of the spiral, so that
    // one Halley step finds it (the first-order guess took two). The slope is taken where the
    // last step began (the guess, usually), not at the root: that differs by under 1e-6 of the
    // angle, well within a guess's error, and keeps its division out of the chain of dependent
    // operations from one handle to the next, which is what a frame's time is.
    const double e = 0.5 * step;
    const double ch_end = h.ch * (1.0 - 0.5 * e * e) - h.sh * e;
    const double sh_end = h.sh * (1.0 - 0.5 * e * e) + h.ch * e;
    const double slope = -h.g_theta / h.g_phi;
    const double began = h.began;
    double drift = slope * began;
    const ChordMemo& m = l.memo;
    if (m.sloped && m.theta == th && m.chord == chord && m.angle > 0.0)
        drift += 0.5 * (slope - m.slope) * (began / m.angle) * began;
    l = {th2, r2 * c2, r2 * s2, {th2, chord, phi, ch_end, sh_end, drift, slope, true}};
    tx = -(c2 - th2 * s2) * inv;
    ty = -(s2 + th2 * c2) * inv;
    return true;
}

// The same from and to a Located.
inline Located behind_within_half_turn(const Spiral& spiral, const Located& from, double chord) {
    Link l{from.place.u, from.pos.x(), from.pos.y(), from.memo};
    double tx = 0.0, ty = 0.0, th2 = 0.0;
    if (!next_link(spiral.b(), chord, l, tx, ty, th2)) return spiral.at({0, th2});
    return Located{{0, l.theta}, {l.x, l.y}, {tx, ty}, l.memo};
}

}  // namespace dragon::spiral_chord
