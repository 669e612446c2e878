// Q2: the first moment two non-adjacent benches touch.
//
// Stepping: at time t every pair of benches has separation g_ij > 0 and, from the benches'
// exact rigid-body velocity fields, a bound L_ij on how fast g_ij can shrink now. Advancing by
//     tau = min_ij g_ij / (kSafety L_ij)
// cannot skip a contact as long as the true closing speed stays below kSafety times the bound
// over the step, which holds with a wide margin because the benches' velocities change slowly
// (tests measure the bound's change over each step and check it stays within the factor).
// Pairs outside the broad phase's margin M have g_ij > M and close at most at the sum of their
// largest point speeds. Collide-separate-collide windows are therefore never stepped over, unlike
// one bisection over the whole run. Near the contact a Newton probe on the closest pair
// brackets the root, which is then refined by bisection to tol::contact_time.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/motion.hpp"
#include "core/sat.hpp"
#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"

namespace dragon {

namespace {

constexpr double kSafety = 2.0;    // slack on the closing-speed bound over one step
constexpr double kMargin = 1.0;    // broad-phase margin, m
constexpr double kMaxStep = 1.0;   // s; keeps the velocity bound's drift over a step small
constexpr double kProbeGap = 2e-3; // m; below this clearance, try to bracket the contact

// Largest point speed of any bench in the frame rotating about the origin at rate w.
double max_speed_in_frame(const Frame& f, const std::vector<BenchMotion>& motion, double w) {
    double worst = 0.0;
    for (size_t k = 0; k < f.benches.size(); ++k) {
        const Corners c = corners(f.benches[k]);
        for (const Vec2 x : c.p) worst = std::max(worst, norm(motion[k].at(x) - w * perp(x)));
    }
    return worst;
}

// The smallest of a few rotating frames' bounds: the fixed frame and the frames turning with
// the mean angular speed of the innermost and outermost benches and halfway between.
double far_speed_bound(const Frame& f, const std::vector<BenchMotion>& motion) {
    double wmin = INFINITY, wmax = -INFINITY;
    for (const BenchMotion& m : motion) {
        const double r2 = dot(m.centre, m.centre);
        if (r2 <= 0.0) continue;
        const double w = cross(m.centre, m.v_centre) / r2;  // angular speed about the origin
        wmin = std::min(wmin, w);
        wmax = std::max(wmax, w);
    }
    double best = max_speed_in_frame(f, motion, 0.0);
    if (!std::isfinite(wmin)) return best;
    for (double k : {0.25, 0.5, 0.75})
        best = std::min(best, max_speed_in_frame(f, motion, wmin + k * (wmax - wmin)));
    return best;
}

struct Approach {
    Clearance clear;
    double safe_step;  // s: no contact can happen sooner
    double rate;       // d/dt of the closest pair's separation now (negative: closing)
};

Approach approach(const Frame& f) {
    Approach a{clearance(f, kMargin), std::numeric_limits<double>::infinity(), 0.0};
    if (f.benches.size() < 3) return a;
    const std::vector<BenchMotion> motion = bench_motions(f);
    // Pairs beyond the margin: their gap shrinks no faster than the sum of the two benches'
    // largest point speeds, measured in any rotating frame (a rotation about the centre moves
    // both points of a pair without changing their distance). The frame that turns with the
    // chain's mean angular speed makes those speeds far smaller than in the fixed frame.
    double fastest = far_speed_bound(f, motion);
    a.safe_step = kMargin / (kSafety * 2.0 * fastest);
    for (const auto& [i, j] : candidate_pairs(f, kMargin)) {
        const Rect& ra = f.benches[static_cast<size_t>(i - 1)];
        const Rect& rb = f.benches[static_cast<size_t>(j - 1)];
        const BenchMotion& ma = motion[static_cast<size_t>(i - 1)];
        const BenchMotion& mb = motion[static_cast<size_t>(j - 1)];
        const double g = sat_gap(ra, rb).gap;  // a lower bound on the distance
        const double bound = separation_rate_bound(ra, ma, mb, g);
        if (bound > 0.0) a.safe_step = std::min(a.safe_step, std::max(g, 0.0) / (kSafety * bound));
    }
    if (a.clear.bench_a > 0) {
        // Separation rate of the closest pair: the witness on b moving away from a along the axis.
        const BenchMotion& ma = motion[static_cast<size_t>(a.clear.bench_a - 1)];
        const BenchMotion& mb = motion[static_cast<size_t>(a.clear.bench_b - 1)];
        const Vec2 q = a.clear.point;
        const Vec2 p = q - std::max(a.clear.distance, 0.0) * a.clear.axis;
        a.rate = dot(a.clear.axis, mb.at(q) - ma.at(p));
    }
    return a;
}

double head_radius(const Frame& f) { return norm(f.handles.front().pos); }

Contact make_contact(const Simulation& sim, double t, int steps) {
    Frame f = sim.frame(t);
    const Clearance c = clearance(f, kMargin);
    return {t, c.bench_a, c.bench_b, head_radius(f), c.point, std::move(f), steps};
}

}  // namespace

std::optional<Contact> first_contact(const Simulation& sim, double t_from, double t_to) {
    sim.require_on_path(t_from, "--from");
    sim.require_on_path(t_to, "--to");
    Frame f;
    int steps = 0;
    double t = t_from;
    sim.frame_into(t, f);
    Approach a = approach(f);
    ++steps;
    if (a.clear.distance <= 0.0) return make_contact(sim, t, steps);

    while (t < t_to) {
        // A pair grazing within rounding of touching, closing too slowly to bound: contact now.
        if (a.safe_step < tol::contact_time) return make_contact(sim, t, steps);
        // Bracket: a Newton probe on the closest pair once it is nearly touching.
        double t_hi = std::numeric_limits<double>::quiet_NaN();
        if (a.clear.distance < kProbeGap && a.rate < 0.0) {
            const double probe = std::min(t_to, t + 1.5 * a.clear.distance / -a.rate);
            sim.frame_into(probe, f);
            ++steps;
            if (clearance(f, kMargin).distance <= 0.0) t_hi = probe;
        }
        if (std::isnan(t_hi)) {
            const double next = std::min({t + a.safe_step, t + kMaxStep, t_to});
            if (next <= t) break;
            sim.frame_into(next, f);
            ++steps;
            const Approach b = approach(f);
            if (b.clear.distance > 0.0) {
                t = next;
                a = b;
                continue;
            }
            t_hi = next;
        }
        // Bisection on [t, t_hi]: clearance > 0 at t, <= 0 at t_hi.
        double lo = t, hi = t_hi;
        while (hi - lo > tol::contact_time) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            sim.frame_into(mid, f);
            ++steps;
            if (clearance(f, kMargin).distance > 0.0) lo = mid; else hi = mid;
        }
        return make_contact(sim, hi, steps);
    }
    return std::nullopt;
}

}  // namespace dragon
