#include <cmath>
#include <numbers>
#include <limits>
#include <utility>

#include "dragon/constants.hpp"
#include "dragon/path.hpp"
#include "dragon/scenario.hpp"
#include "chord_march.hpp"

namespace dragon {

namespace {
constexpr double kPi = std::numbers::pi;
}  // namespace

Spiral::Spiral(double pitch) : pitch_(pitch), b_(pitch / kTwoPi) {}

double Spiral::length_to(double theta) const {
    return 0.5 * b_ * (theta * std::sqrt(1.0 + theta * theta) + std::asinh(theta));
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
    const double c = std::cos(th), s = std::sin(th);
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

// The next handle out along the spiral. With phi = theta' - theta, the squared chord over b^2 is
//   g(phi) = theta^2 + (theta + phi)^2 - 2 theta (theta + phi) cos(phi),
//   g'(phi) = 2 [(theta + phi) - theta cos(phi) + theta (theta + phi) sin(phi)] > 0 on (0, pi],
// so when g(pi) = (2 theta + pi)^2 >= (chord / b)^2 there is exactly one root in (0, pi]: the
// nearest one, found by Halley's method on that bracket (within_half_turn). Closer to the centre
// the chord may reach round past the far side; the general curvature-bounded march handles that
// case (round_the_centre).
std::optional<Located> Spiral::behind(const Located& from, double chord) const {
    if (2.0 * from.place.u + kPi < chord / b_) return behind_round_the_centre(from, chord);
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

namespace {

// A memo's drift larger than this (rad) is no guess worth taking: the circle model starts instead.
constexpr double kMemoDrift = 0.1;
// Below this argument asin's series (four terms, relative error under 2e-5) is first guess enough.
constexpr double kAsinSeries = 0.5;
// Halley steps below this (rad) move the half angle's cos and sin by the angle-sum rule with the
// step's series (|step / 2| <= 5e-4: the dropped terms are below 1e-22) instead of a sincos.
constexpr double kSeriesStep = 1e-3;

// cos and sin of d from their series: |d| <= 0.05 leaves the dropped terms below 1e-20.
std::pair<double, double> cos_sin_small(double d) {
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

FirstGuess first_guess(const ChordMemo& memo, double th, double chord, double k) {
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
    return {x < 1.0 ? 2.0 * std::asin(x) : 0.5 * kPi};
}

// Halley's result: the angle, the last step, and the cos and sin of the angle (c, s) and of its
// half (ch, sh) at the start of that step.
struct HalleyRoot {
    double phi, step;
    double c, s, ch, sh;
};

// Halley's method (cubic convergence) with a bisection fallback on (0, pi]. g' and g'' reuse the
// same cos and sin, so each iteration costs one sincos. g is summed as
//   g(phi) = phi^2 + 2 theta (theta + phi) (1 - cos phi),
// two positive terms: the textbook form theta^2 + (theta + phi)^2 - 2 theta (theta + phi) cos phi
// cancels theta^2 against itself, which far out on the spiral (a link of 1 m at radius 70 km:
// phi ~ 1e-5, theta ~ 1e4) left chords wrong by 1e-6 relative (found by tests/fuzz/fuzz_chain).
// The step is judged relative to phi for the same reason: a root of 1e-5 rad is not found
// to 1e-6 rad.
HalleyRoot halley(double th, double k2, FirstGuess guess) {
    double lo = 0.0, hi = kPi;
    double phi = guess.phi, c = 1.0, s = 0.0, step = 0.0;
    double ch = guess.cos_half, sh = guess.sin_half;
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
            ch = std::cos(0.5 * phi);
            sh = std::sin(0.5 * phi);
        }
        const double one_minus_c = 2.0 * sh * sh;
        c = 1.0 - one_minus_c;
        s = 2.0 * sh * ch;
        const double g = phi * phi + 2.0 * th * t2 * one_minus_c - k2;
        if (g < 0.0) lo = phi; else hi = phi;
        const double dg = 2.0 * (phi + th * one_minus_c + th * t2 * s);
        const double ddg = 2.0 * (1.0 + 2.0 * th * s + th * t2 * c);
        double next = phi - 2.0 * g * dg / (2.0 * dg * dg - g * ddg);
        // Closed bracket: at (or a rounding step from) the root, phi itself is an end of it.
        if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
        step = next - phi;
        phi = next;
        if (std::abs(step) <= tol::halley_step * phi || hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * (th + kPi)) break;
    }
    return {phi, step, c, s, ch, sh};
}

}  // namespace

std::optional<Located> Spiral::behind_within_half_turn(const Located& from, double chord) const {
    const double th = from.place.u;
    const double k = chord / b_;
    const HalleyRoot h = halley(th, k * k, first_guess(from.memo, th, chord, k));
    const double phi = h.phi, step = h.step;
    const double th2 = th + phi;
    if (th < 1.0 || std::abs(step) > tol::halley_step * phi) return at({0, th2});
    // cos and sin of the last step's end from those of its start (|step| <= 1e-6 phi, so the
    // dropped terms are below 1e-18), then of theta' = theta + phi by the angle-sum rule, with cos and
    // sin of theta read off the previous handle's position: one sincos per handle saved.
    const double cp = h.c * (1.0 - 0.5 * step * step) - h.s * step;
    const double sp = h.s * (1.0 - 0.5 * step * step) + h.c * step;
    const double r0 = b_ * th;
    const double c0 = from.pos.x() / r0, s0 = from.pos.y() / r0;
    const double c2 = c0 * cp - s0 * sp, s2 = s0 * cp + c0 * sp;
    const double r2 = b_ * th2;
    const double inv = 1.0 / std::sqrt(1.0 + th2 * th2);
    // The memo for the next link: the half angle's cos and sin moved by the last step like cp and
    // sp above, and the drift phi * dphi/dtheta = -phi g_theta / g_phi, with
    // g_theta = 2 (2 theta + phi)(1 - cos phi).
    const double e = 0.5 * step;
    const double ch_end = h.ch * (1.0 - 0.5 * e * e) - h.sh * e;
    const double sh_end = h.sh * (1.0 - 0.5 * e * e) + h.ch * e;
    const double one_minus_cp = 2.0 * sh_end * sh_end;
    const double g_phi = 2.0 * (phi + th * one_minus_cp + th * th2 * sp);
    const double g_theta = 2.0 * (th + th2) * one_minus_cp;
    const ChordMemo next{th2, chord, phi, ch_end, sh_end, -phi * g_theta / g_phi};
    return Located{{0, th2}, {r2 * c2, r2 * s2}, {-(c2 - th2 * s2) * inv, -(s2 + th2 * c2) * inv}, next};
}

}  // namespace dragon
