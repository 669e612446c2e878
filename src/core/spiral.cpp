#include <cmath>
#include <limits>
#include <utility>

#include "dragon/constants.hpp"
#include "dragon/path.hpp"
#include "dragon/scenario.hpp"
#include "chord_march.hpp"
#include "spiral_chord.hpp"
#include "dragon/portable_math.hpp"

namespace dragon {

Spiral::Spiral(double pitch) : pitch_(pitch), b_(pitch / kTwoPi) {}

double Spiral::length_to(double theta) const {
    return 0.5 * b_ * (theta * std::sqrt(1.0 + theta * theta) + math::asinh(theta));
}

// Inverts length_to by Newton's method on L(theta) - length, L' = b sqrt(1 + theta^2) > 0.
// L is convex and increasing, so Newton from a point right of the root stays right of it and
// converges monotonically; start from the upper bound theta0 = sqrt(2 length / b) + 1 >= root
// (L(theta) >= b theta^2 / 2 gives root <= sqrt(2 length / b)).
double Spiral::theta_at_length(double length) const {
    if (length <= 0.0) return 0.0;
    double theta = std::sqrt(2.0 * length / b_) + 1.0;
    for (int it = 0; it < tol::max_newton; ++it) {
        const double f = length_to(theta) - length;
        const double step = f / (b_ * std::sqrt(1.0 + theta * theta));
        theta = std::max(0.0, theta - step);
        if (std::abs(step) <= tol::arc_relative * (1.0 + theta)) break;
    }
    return theta;
}

Located Spiral::at(Place p) const {
    const double th = p.u;
    const double c = math::cos(th), s = math::sin(th);
    const double r = b_ * th;
    // Travel is towards decreasing theta: tangent = -dP/dtheta / |dP/dtheta|.
    const double inv = 1.0 / std::sqrt(1.0 + th * th);
    return {p, {r * c, r * s}, {-(c - th * s) * inv, -(s + th * c) * inv}};
}

double Spiral::arc(Place p) const { return -length_to(p.u); }

Located Spiral::at_arc(double s) const { return at({0, theta_at_length(-s)}); }

double Spiral::s_min() const { return -std::numeric_limits<double>::infinity(); }

double Spiral::curvature_at(double theta) const {
    const double q = 1.0 + theta * theta;
    return (theta * theta + 2.0) / (b_ * q * std::sqrt(q));
}

// Clockwise travel: the path turns right, so the signed curvature is negative.
double Spiral::curvature(Place p) const { return -curvature_at(p.u); }

// curvature_at falls monotonically in theta (its derivative is -theta (theta^2 + 4) / (b
// (1 + theta^2)^(5/2))), so bisection on a bracket finds where it equals k. Far out it is
// ~1 / (b theta), so theta = 2 / (b k) + 2 is past the root.
double Spiral::theta_of_curvature(double k) const {
    if (k >= 2.0 / b_) return 0.0;
    double lo = 0.0, hi = 2.0 / (b_ * k) + 2.0;
    while (curvature_at(hi) > k) hi *= 2.0;
    for (int it = 0; it < 200 && hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (curvature_at(mid) > k ? lo : hi) = mid;
    }
    return hi;  // the side where the curvature is at most k
}

double Spiral::turning(Place rear, Place front) const {
    return std::abs(tangent_angle(rear.u) - tangent_angle(front.u));
}

// Behind a place means farther out, where the curvature is smaller.
double Spiral::curvature_bounded_before(double k) const {
    if (k >= 2.0 / b_) return s_max();
    return -length_to(theta_of_curvature(k));
}

// Ahead lies the centre, where the curvature is 2 / b.
double Spiral::curvature_bounded_after(double k) const {
    return k >= 2.0 / b_ ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
}

// The next handle out along the spiral: within half a turn, one root found by Halley's method
// (core/spiral_chord.hpp). Closer to the centre the chord may reach round past the far side; the
// general curvature-bounded march handles that case (round_the_centre).
std::optional<Located> Spiral::behind(const Located& from, double chord) const {
    if (!spiral_chord::within_half_turn(b_, from.place.u, chord)) return behind_round_the_centre(from, chord);
    return behind_within_half_turn(from, chord);
}

std::optional<Located> Spiral::behind_round_the_centre(const Located& from, double chord) const {
    // Every root lies where the spiral's radius b theta' is within the chord of |q| (triangle
    // inequality): none before (d - |q|) / b, where the march may start, and none past
    // (d + |q|) / b, where it may stop (a radian later, so that rounding cannot put the root
    // past the end).
    const double r0 = norm(from.pos);
    const double start = std::max(from.place.u, (chord - r0) / b_);
    const auto u = march_to_chord(SpiralPiece{b_}, SpiralBound{b_}, from.pos, chord, start, +1.0,
                                  (chord + r0) / b_ + 1.0, kSpiralMarchStep);
    if (!u) return std::nullopt;
    return at({0, *u});
}

std::optional<Located> Spiral::behind_within_half_turn(const Located& from, double chord) const {
    return spiral_chord::behind_within_half_turn(*this, from, chord);
}

}  // namespace dragon
