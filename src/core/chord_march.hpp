// The general "nearest chord root" search along one smooth path piece.
//
// Given a piece P(u), a point q and a chord d, find the first u reached from u0 (moving in
// direction dir = +1 or -1) where |P(u) - q| = d. With h(u) = |P(u) - q|^2 - d^2 < 0 at the
// current point a and M >= |h''| wherever |P - q| <= d on the step, Taylor's bound
//     h(a + dir*delta) <= h(a) + p delta + M delta^2 / 2,   p = dir * h'(a),
// stays negative for every delta below the positive root delta* of the right-hand side. So the
// march a <- a + dir*delta* can never step over a root (it only approaches the first one), and
// near a simple root delta* tends to the Newton step, so convergence is quadratic.
// h'' = 2 (|P'|^2 + (P - q) . P''), hence M = 2 (max |P'|^2 + d max |P''|) on the step.
#pragma once

#include "dragon/errors.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "dragon/constants.hpp"
#include "dragon/geometry.hpp"
#include "dragon/portable_math.hpp"

namespace dragon {

struct PieceSample {
    Vec2 p = Vec2::Zero();  // P(u)
    Vec2 du = Vec2::Zero();  // P'(u)
};

// eval(u) -> PieceSample; bound(ua, ub) -> max over [min, max] of |P'|^2 and |P''| as
// {first, second}. Precondition: u0 lies on the piece; the search stops at u_end, which must be
// finite (an unbounded piece is clamped by its caller to where the root must lie).
// Returns nullopt when |P(u) - q| < d all the way to u_end.
//
// Far from the root the march moves up to max_step at a time; near it, it converges
// quadratically. Where the piece runs nearly along the chord's circle (a spiral turn round a
// point near the centre) the curvature bound is loose and the steps shorter, so the allowance is
// tol::max_march steps per max_step of the range: running out of it means a broken bound, a
// bug, and throws SolverError rather than return a point that is not at the chord.
template <class Eval, class Bound>
std::optional<double> march_to_chord(Eval eval, Bound bound, const Vec2& q, double chord, double u0,
                                     double dir, double u_end, double max_step) {
    const double d2 = chord * chord;
    const double allowance = tol::max_march * (1.0 + std::ceil(std::abs(u_end - u0) / max_step));
    if (!(allowance < 1e8))
        throw SolverError("march_to_chord: the range to search is unbounded or too long");
    const long steps = static_cast<long>(allowance);
    double a = u0;
    for (long it = 0; it < steps; ++it) {
        const PieceSample s = eval(a);
        const Vec2 w = s.p - q;
        const double h = dot(w, w) - d2;
        if (h >= 0.0) return a;  // at (or, from a join, already past) the chord
        const double p = dir * 2.0 * dot(w, s.du);
        const double room = dir * (u_end - a);
        if (room <= 0.0) return std::nullopt;
        const double span = std::min(max_step, room);
        const auto [d1sq, d2abs] = bound(a, a + dir * span);
        const double m = 2.0 * (d1sq + chord * d2abs);
        // Positive root of (m/2) x^2 + p x + h = 0, in the cancellation-free form.
        double delta = -2.0 * h / (p + std::sqrt(p * p - 2.0 * m * h));
        // Past the span the bound is unproven: stop there and take a fresh bound. At the end
        // of the piece (landing on u_end exactly) the next pass either finds h >= 0 there or
        // runs out of room. Only a step the root itself made tiny means convergence: a step cut
        // short by the piece's end is not one (that took a point short of the chord, at the
        // piece's end, for a root; found by tests/fuzz/fuzz_chain).
        if (delta >= span) {
            a = span == room ? u_end : a + dir * span;
            continue;
        }
        const double next = a + dir * delta;
        if (delta <= 4.0 * std::numeric_limits<double>::epsilon() * (1.0 + std::abs(a))) return next;
        a = next;
    }
    throw SolverError("march_to_chord: no convergence within its allowance of steps");
}

// The spiral P(theta) = b theta (cos theta, sin theta) as a march piece, and the bounds
// |P'|^2 = b^2 (1 + theta^2) and |P''| = b sqrt(4 + theta^2), both growing with |theta|, so their
// maxima over a step are at its end farther from the centre.
struct SpiralPiece {
    double b;
    PieceSample operator()(double u) const {
        const double c = math::cos(u), s = math::sin(u);
        return {{b * u * c, b * u * s}, {b * (c - u * s), b * (s + u * c)}};
    }
};
struct SpiralBound {
    double b;
    std::pair<double, double> operator()(double ua, double ub) const {
        const double t = std::max(std::abs(ua), std::abs(ub));
        return {b * b * (1.0 + t * t), b * std::sqrt(4.0 + t * t)};
    }
};
// Largest step of a spiral march, rad: keeps the curvature bound local (it is taken at the
// step's far end, where |P'| and |P''| are largest).
inline constexpr double kSpiralMarchStep = 0.5;

}  // namespace dragon
