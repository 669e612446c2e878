// The S-curve's exact design from the pitch, the entry radius and the radius ratio.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "dragon/constants.hpp"
#include "dragon/turnaround.hpp"
#include "dragon/portable_math.hpp"

namespace dragon {

namespace {


void require_positive(Key name, double v) {
    if (!std::isfinite(v) || v <= 0.0)
        throw InputError(name, error_value(v), "it must be a finite number > 0");
}

// x wrapped into (0, 2 pi]: a sweep angle of an arc.
double sweep(double x) {
    double w = std::fmod(x, kTwoPi);
    if (w <= 0.0) w += kTwoPi;
    return w;
}

double angle_of(const Vec2& v) { return math::atan2(v.y(), v.x()); }

// Farthest distance from the origin on the arc about c of radius r that starts at angle u0 and
// sweeps `angle` (sign = direction): |c| + r if the arc passes the direction of c, else 0
// (the caller also counts the end points).
double arc_reach(const Vec2& c, double r, double u0, double angle) {
    const double towards = angle_of(c);
    const double along = angle > 0.0 ? sweep(towards - u0) : sweep(u0 - towards);
    return along <= std::abs(angle) ? norm(c) + r : 0.0;
}

}  // namespace

// With unit normals n_a = perp(T_A), n_b = perp(T_B) (T the travel directions), arc 1's centre
// is C1 = A + sigma r1 n_a and arc 2's, turning the other way, C2 = B - sigma r2 n_b
// (sigma = -1: arc 1 turns clockwise). The arcs touch externally: |C1 - C2| = r1 + r2. With
// D = A - B and r1 = k r2, squaring gives the quadratic in r2
//     2k (n_a . n_b - 1) r2^2 + 2 sigma D . (k n_a + n_b) r2 + |D|^2 = 0.
// The leading coefficient is <= 0 and the constant > 0, so exactly one root is positive when
// sigma D . (k n_a + n_b) < 0; it is taken in the cancellation-free form
//     r2 = 2|D|^2 / (-q1 + sqrt(q1^2 - 4 q2 |D|^2)).
// Here T_B = T_A (the coil-out spiral is the coil-in one turned by pi and travelled backwards),
// so q2 = 0 and r1 + r2 = R sqrt(1 + theta^2) / theta exactly: the same for every ratio.
SCurve design_s_curve(double pitch, double entry_radius, double ratio) {
    require_positive(Key::turn_pitch, pitch);
    require_positive(Key::entry_radius, entry_radius);
    require_positive(Key::arc_ratio, ratio);

    const Spiral spiral(pitch);
    SCurve d;
    d.pitch = pitch;
    d.entry_radius = entry_radius;
    d.entry_theta = entry_radius / spiral.b();
    d.ratio = ratio;
    const Located a = spiral.at({0, d.entry_theta});
    d.entry = a.pos;
    d.exit = -a.pos;
    d.direction = a.tangent;
    const Vec2 tangent_b = a.tangent;  // coil-out travel direction at B

    const Vec2 na = perp(d.direction), nb = perp(tangent_b);
    const Vec2 gap = d.entry - d.exit;
    const double k = ratio;
    const double lin = dot(gap, k * na + nb);
    if (!(lin > 0.0)) {
        throw InputError(fmt::format("turn radius {} with turn pitch {} admits no S-curve: the "
                                     "spirals' normals at the entry and exit do not face each other",
                                     entry_radius, pitch));
    }
    const double sigma = -1.0;
    const double q2 = 2.0 * k * (dot(na, nb) - 1.0);
    const double q1 = 2.0 * sigma * lin;
    const double q0 = dot(gap, gap);
    d.r2 = 2.0 * q0 / (-q1 + std::sqrt(q1 * q1 - 4.0 * q2 * q0));
    d.r1 = k * d.r2;
    d.c1 = d.entry + sigma * d.r1 * na;
    d.c2 = d.exit - sigma * d.r2 * nb;
    d.joint = d.c1 + (d.r1 / (d.r1 + d.r2)) * (d.c2 - d.c1);

    // Arc 1 runs clockwise from A to the joint, arc 2 counter-clockwise from the joint to B.
    d.angle1 = sweep(angle_of(d.entry - d.c1) - angle_of(d.c2 - d.c1));
    d.angle2 = sweep(angle_of(d.exit - d.c2) - angle_of(d.c1 - d.c2));
    d.length1 = d.r1 * d.angle1;
    d.length2 = d.r2 * d.angle2;
    d.length = d.length1 + d.length2;
    if (!std::isfinite(d.length) || !(d.r2 > 0.0)) {
        throw InputError(fmt::format("turn radius {} with turn pitch {} and arc ratio {} admits no "
                                     "S-curve", entry_radius, pitch, ratio));
    }

    d.max_radius = std::max({norm(d.entry), norm(d.exit), norm(d.joint),
                             arc_reach(d.c1, d.r1, angle_of(d.entry - d.c1), -d.angle1),
                             arc_reach(d.c2, d.r2, angle_of(d.c1 - d.c2), d.angle2)});
    return d;
}

SCurve design_s_curve(const Scenario& s) {
    return design_s_curve(s.path.turn_pitch, s.path.turn_radius, s.path.arc_ratio);
}

}  // namespace dragon
