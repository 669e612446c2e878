// Bounds on how fast benches far apart can close in (contact_bounds.hpp).
#include "contact_bounds.hpp"

#include <algorithm>
#include <cmath>

namespace dragon::contact {

// Speeds and rates here are per metre of head travel and steps are head travel, m: the search
// evaluates the motion at 1 m/s (first_contact.cpp).
//
// Pairs beyond the broad phase's margin, bounded group by group. A bench's velocity field seen
// in a frame turning about the origin at rate w is v_c - w perp(c) + (omega - w) perp(x - c), so
// its points move there at most S(w) = |v_c - w perp(c)| + |omega - w| R (R: half-diagonal).
// The distance between two points does not depend on the frame, so it shrinks no faster than
// S_a(w) + S_b(w) for any one w. Benches are grouped in runs along the chain; each group has a
// rate w_G (its members' mean angular speed about the origin), V_G = max S_k(w_G), and
// rho_G = max |c_k| + R_k, which give S_k(w) <= V_G + |w - w_G| rho_G for its members. For two
// groups, the best w between w_G and w_H bounds every member pair's closing speed by
//     W_GH = V_G + V_H + |w_G - w_H| min(rho_G, rho_H),
// and each such pair not among the broad phase's candidates is more than the margin apart, and
// at least as far apart as the groups' bounding circles. Neighbouring turns turn at nearly the
// same rate, so W is far below twice the largest point speed in any single frame.
//
// That bound is weak for groups on different turns: they slide past each other at |w_G - w_H|
// times the radius, without closing. A second bound sees this. Any point x of bench k moves at
// (v_c - omega perp(c)) + omega perp(x), and perp(x) is square to x, so |x| changes at most at
// u_k = |v_c - omega perp(c)| (small: the chain turns about the origin almost rigidly). If a
// group's radii lie in [lo_G, hi_G] and another's in [lo_H, hi_H] with lo_H > hi_G, every member
// pair is at least lo_H - hi_G apart (|x - y| >= |y| - |x|), a gap that shrinks no faster than
// U_G + U_H (U: the largest u_k). A group pair may take the better of the two steps.
namespace {
constexpr int kGroup = 8;  // benches per group
}  // namespace

void radial_extents(const Frame& f, const std::vector<BenchMotion>& motion, std::vector<Radial>& out) {
    out.resize(f.benches.size());
    for (size_t k = 0; k < f.benches.size(); ++k) out[k] = radial_extent(f.benches[k], motion[k]);
}

double radial_gap(const Radial& a, const Radial& b) { return std::max(b.lo - a.hi, a.lo - b.hi); }
double radial_step(const Radial& a, const Radial& b, double rate_safety) {
    const double gap = radial_gap(a, b);
    if (!(gap > 0.0)) return 0.0;
    const double closing = a.speed + b.speed;
    return closing > 0.0 ? gap / (rate_safety * closing) : INFINITY;
}

namespace {
struct Group {
    Vec2 centre = Vec2::Zero();
    double radius;  // bounding circle of the members' rectangles
    double rate;    // w_G
    double speed;   // V_G
    double reach;   // rho_G
    Radial radii;   // the members' radii all lie in [lo, hi] and change at most at U_G
};
}  // namespace

double far_pairs_step(const Frame& f, const std::vector<BenchMotion>& motion, const std::vector<double>& half_diagonals,
                      const std::vector<Radial>& radial, double margin, std::vector<GroupRecord>& record,
                      double rate_safety, const std::vector<GroupRecord>* last, double step, bool* broken) {
    const size_t n = f.benches.size();
    std::vector<Group> groups;
    groups.reserve(n / kGroup + 1);
    for (size_t g0 = 0; g0 < n; g0 += kGroup) {
        const size_t g1 = std::min(n, g0 + kGroup);
        Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
        double rate = 0.0;
        int rated = 0;
        for (size_t k = g0; k < g1; ++k) {
            const Vec2 c = motion[k].centre;
            lo = {std::min(lo.x(), c.x()), std::min(lo.y(), c.y())};
            hi = {std::max(hi.x(), c.x()), std::max(hi.y(), c.y())};
            const double r2 = dot(c, c);
            if (r2 > 0.0) rate += cross(c, motion[k].v_centre) / r2, ++rated;
        }
        Group g{0.5 * (lo + hi), 0.0, rated ? rate / rated : 0.0, 0.0, 0.0, {INFINITY, 0.0, 0.0}};
        for (size_t k = g0; k < g1; ++k) {
            const BenchMotion& m = motion[k];
            const double diagonal = half_diagonals[k];
            g.radius = std::max(g.radius, norm(m.centre - g.centre) + diagonal);
            g.speed = std::max(g.speed, norm(m.v_centre - g.rate * perp(m.centre)) + std::abs(m.omega - g.rate) * diagonal);
            g.reach = std::max(g.reach, norm(m.centre) + diagonal);
            g.radii = {std::min(g.radii.lo, radial[k].lo), std::max(g.radii.hi, radial[k].hi),
                       std::max(g.radii.speed, radial[k].speed)};
        }
        groups.push_back(g);
    }
    double out = INFINITY;
    record.clear();
    const bool check = last && broken && last->size() == groups.size() * (groups.size() + 1) / 2;
    for (size_t a = 0; a < groups.size(); ++a) {
        const Group& ga = groups[a];
        for (size_t b = a; b < groups.size(); ++b) {
            const Group& gb = groups[b];
            const double closing = ga.speed + gb.speed + std::abs(ga.rate - gb.rate) * std::min(ga.reach, gb.reach);
            const double apart = std::max(margin, norm(ga.centre - gb.centre) - ga.radius - gb.radius);
            const double pair_step = closing > 0.0 ? apart / (rate_safety * closing) : INFINITY;
            out = std::min(out, std::max(pair_step, radial_step(ga.radii, gb.radii, rate_safety)));
            const GroupRecord r{apart, closing, radial_gap(ga.radii, gb.radii), ga.radii.speed + gb.radii.speed};
            if (check) {
                // The step held for these groups if, at the speeds measured here, either gap they
                // had at its start lasts the whole step.
                const GroupRecord& was = (*last)[record.size()];
                const bool held = closing * step <= was.apart * (1.0 + tol::promise_relative) ||
                                  (was.radial_gap > 0.0 && r.radial_closing * step <= was.radial_gap * (1.0 + tol::promise_relative));
                if (!held) *broken = true;
            }
            record.push_back(r);
        }
    }
    return out;
}

}  // namespace dragon::contact
