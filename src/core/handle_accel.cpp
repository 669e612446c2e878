// Bounds on each handle's second derivative in head travel over a step (handle_accel.hpp).
#include "handle_accel.hpp"

#include <algorithm>
#include <cmath>

#include "gentle_link.hpp"
#include "interval.hpp"
#include "path_part.hpp"
#include "dragon/geometry.hpp"
#include "dragon/portable_math.hpp"

namespace dragon::contact {

namespace {

// The signed curvature's range between places a (behind) and b.
Iv curvature_between(const Path& path, const Place& a, const Place& b) {
    const auto [lo, hi] = curvature_range(path, a, b);
    return {lo, hi};
}

// A lower bound on cos(t) and an upper bound on sin(t) for 0 <= t < pi/2, without a call to
// either where t is small: cos t >= 1 - t^2 / 2 and sin t <= t.
double cos_below(double t) { return t < 1.0 ? 1.0 - 0.5 * t * t : math::cos(t); }
double sin_above(double t) { return std::min(t, 1.0); }

// The interval of a value known at the step's two ends that can move by at most `turn` from
// either over the step: the ends' range widened by half of it (the moving value is below both
// v0 + turn s and v1 + turn (1 - s), so below their crossing), within [lo, hi].
Iv widened(double v0, double v1, double turn, double lo, double hi) {
    return {std::max(lo, std::min(v0, v1) - 0.5 * turn), std::min(hi, std::max(v0, v1) + 0.5 * turn)};
}

// Relative and absolute (1/m) widening of each bound: the interval arithmetic's rounding (a few
// ulps of each of a few dozen operations a link) is far below the relative one, and the frames'
// own (handle places to ~1e-14 m, so angles to ~1e-14 rad, which matter most where a bound is
// near zero, as on a circle) far below the absolute one.
constexpr double kAccelRelativeSlack = 1e-9;
constexpr double kAccelAbsoluteSlack = 1e-12;

}  // namespace

bool handle_accel_bounds(const Path& path, const BenchSpec& spec, const Frame& f0, const Frame& f1,
                         const std::vector<double>& hull_turning, const std::vector<double>& own_turning,
                         std::vector<double>& accel, std::vector<double>& speed) {
    const size_t nh = std::min(f0.handles.size(), f1.handles.size());
    accel.resize(nh);
    speed.resize(nh);
    if (nh == 0) return true;
    const double head0 = f0.handles[0].speed, head1 = f1.handles[0].speed;
    if (!(head0 > 0.0) || !(head1 > 0.0)) return false;
    // m of head travel over the step.
    const double h = std::abs(f1.head_arc - f0.head_arc);
    const auto widen = [](double bound) { return bound * (1.0 + kAccelRelativeSlack) + kAccelAbsoluteSlack; };
    // Handle k's curvature over its arc, and its speed ratio's bound over the step.
    Iv kappa_front = curvature_between(path, f0.handles[0].place, f1.handles[0].place);
    double v_bound = 1.0;  // the head: v_0 = 1 throughout
    double a_bound = 0.0;  // and v_0' = 0
    accel[0] = widen(magnitude(kappa_front));
    speed[0] = 1.0;
    for (size_t k = 0; k + 1 < nh; ++k) {
        const Handle& F0 = f0.handles[k];
        const Handle& F1 = f1.handles[k];
        const Handle& R0 = f0.handles[k + 1];
        const Handle& R1 = f1.handles[k + 1];
        const double tau = hull_turning[k];
        if (!(tau < gentle::kMaxLinkTurning)) return false;
        const double d = spec.link_length(static_cast<int>(k) + 1);
        const Iv kappa_rear = curvature_between(path, R0.place, R1.place);
        // The ends' sines and cosines of the angles from the link to each tangent.
        const Vec2 u0 = (F0.pos - R0.pos).normalized(), u1 = (F1.pos - R1.pos).normalized();
        // How far each angle can turn over the step (sine and cosine move by no more), per unit
        // of the front's arc: the link at |w| <= (sin tau + rho sin tau) / d, the tangents at
        // |kappa_F| and rho |kappa_R|. The front's arc is at most its chord over the cosine of
        // its own turning (every tangent on it within that of the chord's direction).
        const double cos_tau = cos_below(tau), sin_tau = sin_above(tau);
        const double own_turn = own_turning[k];
        if (!(own_turn < gentle::kMaxLinkTurning)) return false;
        const double arc_front = norm(F1.pos - F0.pos) / cos_below(own_turn);
        // The angles' intervals from a bound on rho and |w|: first the hull's (rho <= 1 /
        // cos tau, |w| <= (sin tau + rho sin tau) / d), then once more from the intervals those
        // give (each holds over the whole step, so the second is as sound as the first).
        // A sine moves by at most the angle; a cosine by at most the angle times the largest
        // |sine| on the way.
        Iv sF, cF, sR, cR, rho{0.0, 1.0 / cos_tau}, w{-1.0, 1.0};
        double w_most = sin_tau * (1.0 + rho.hi) / d;
        for (int pass = 0; pass < 2; ++pass) {
            const double turnF = arc_front * (magnitude(kappa_front) + w_most);
            const double turnR = arc_front * (rho.hi * magnitude(kappa_rear) + w_most);
            sF = widened(cross(u0, F0.tangent), cross(u1, F1.tangent), turnF, -sin_tau, sin_tau);
            sR = widened(cross(u0, R0.tangent), cross(u1, R1.tangent), turnR, -sin_tau, sin_tau);
            cF = widened(dot(u0, F0.tangent), dot(u1, F1.tangent), turnF * magnitude(sF), cos_tau, 1.0);
            cR = widened(dot(u0, R0.tangent), dot(u1, R1.tangent), turnR * magnitude(sR), cos_tau, 1.0);
            rho = cF / cR;
            w = (1.0 / d) * (sF - rho * sR);
            w_most = magnitude(w);
        }
        const Iv rho_rate = (sF * (w - kappa_front) * cR - cF * sR * (w - rho * kappa_rear)) / (cR * cR);
        // v_{k+1}' = v_k' rho + v_k^2 (d rho / d sigma_k).
        a_bound = widen(a_bound * rho.hi + v_bound * v_bound * magnitude(rho_rate));
        const double v_ends = std::max(std::abs(R0.speed / head0), std::abs(R1.speed / head1));
        v_bound = widen(v_ends + 0.5 * h * a_bound);
        const double bend = v_bound * v_bound * magnitude(kappa_rear);
        accel[k + 1] = widen(std::sqrt(a_bound * a_bound + bend * bend));
        speed[k + 1] = v_bound;
        kappa_front = kappa_rear;
    }
    return true;
}

}  // namespace dragon::contact
