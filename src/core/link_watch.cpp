#include "link_watch.hpp"
#include "golden_section.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

namespace dragon::jam {

namespace {

// The health's samples: about one per this much turning of the path between the handles (rad).
// The least sample is then refined by golden-section search.
constexpr double kSampleTurn = 0.05;
constexpr int kMaxSamples = 400;
// Golden-section search on the health stops at this bracket of the piece's parameter: the
// health is then known to ~1e-24 m near a smooth minimum and to ~1e-12 m at a kink.
constexpr double kHealthArc = 1e-12;

// The |curvature| a handle may meet within `reach` of path either way: its own, and the span of
// every piece whose stretch of path lies that close.
std::pair<double, double> reachable_curvature(const Path& path, const Handle& h, double here, double reach) {
    double lo = here, hi = here;
    const int pieces = path.piece_count();
    if (pieces == 1) return {lo, hi};
    const double s = path.arc(h.place);
    for (int p = 0; p < pieces; ++p) {
        if (p == h.place.piece) continue;
        const double begin = path.piece_begin(p), end = p + 1 < pieces ? path.piece_begin(p + 1) : INFINITY;
        const double gap = s < begin ? begin - s : s > end ? s - end : 0.0;
        if (gap <= reach) {
            const auto [a, b] = path.curvature_span(p);
            lo = std::min(lo, a), hi = std::max(hi, b);
        }
    }
    return {lo, hi};
}

LinkCheck check_shape(const Path& path, const Handle& front, const Handle& rear, double chord);

}  // namespace

Calm calm_for(const Path& path, double chord) {
    const double k = kCalmBend / chord;
    return {path.curvature_bounded_before(k), path.curvature_bounded_after(k)};
}

LinkCheck check_link(const Path& path, const Handle& front, const Handle& rear, double chord, const Calm& calm,
                     double dir) {
    const double vf = front.speed, vr = rear.speed;
    LinkCheck out;
    // On calm path: certified until the front, moving ahead, reaches the calm stretch's end (or
    // the rear, moving back, its start); for ever while they move the other way. A margin of one
    // (the step's allowance) stands in for it.
    double calm_step = -1.0;
    if (calm.before > -INFINITY) {
        if (const double sf = path.arc(front.place); sf <= calm.before)
            calm_step = dir * vf > 0.0 ? (calm.before - sf) / (kSafety * dir * vf) : INFINITY;
    }
    if (calm.after < INFINITY) {
        if (const double sr = path.arc(rear.place); sr >= calm.after)
            calm_step = std::max(calm_step, dir * vr < 0.0 ? (sr - calm.after) / (kSafety * -dir * vr) : INFINITY);
    }
    if (calm_step >= kMaxStep) {
        out.calm = true;
        out.margin = 1.0;
        out.step = calm_step;
        return out;
    }
    // Near the calm stretch's end its step shrinks towards zero: the link is looked at instead,
    // and keeps whichever certificate lasts longer, with that certificate's own margin (a step
    // taken on the calm one is checked as a calm link's; with the shape's margin and the calm
    // step, a turning that grew faster than its margin allowed over the calm step broke the
    // bound at every length, and the walk crept on by the checks' rounding allowance).
    out = check_shape(path, front, rear, chord);
    if (calm_step > out.step) {
        out = LinkCheck{};
        out.calm = true;
        out.margin = 1.0;
        out.step = calm_step;
    }
    return out;
}

namespace {

// The link's own shape: its turning when gentle, else its health.
LinkCheck check_shape(const Path& path, const Handle& front, const Handle& rear, double chord) {
    const double vf = front.speed, vr = rear.speed;
    LinkCheck out;
    const double turn = path.turning(rear.place, front.place);
    const double kf = path.curvature(front.place), kr = path.curvature(rear.place);
    out.turn = turn;
    if (turn < kGentleTurn) {
        // Every tangent between the handles is within `turn` of the one at any point, so the
        // distance from the front handle grows at least at cos(turn) > 0 going back: one simple
        // root, no other within reach. The turning changes only through its ends, at
        // |kf| vf - |kr| vr (each piece's curvature keeps its sign): small while both ends see
        // the same curvature, as on one arc. Where an end may cross into another piece within
        // the longest step, the curvatures it could meet there count too; a tenth of the sum on
        // top covers speeds and curvatures that drift over the step.
        out.gentle = true;
        out.margin = kQuarterTurn - turn;
        const auto [lf, hf] = reachable_curvature(path, front, std::abs(kf), kSafety * std::abs(vf) * kMaxStep);
        const auto [lr, hr] = reachable_curvature(path, rear, std::abs(kr), kSafety * std::abs(vr) * kMaxStep);
        double rate = 0.0;
        for (const double a : {lf, hf})
            for (const double b : {lr, hr}) rate = std::max(rate, std::abs(a * vf - b * vr));
        rate += 0.1 * (hf * std::abs(vf) + hr * std::abs(vr));
        out.step = rate > 0.0 ? out.margin / (kSafety * rate) : INFINITY;
        return out;
    }

    out.gentle = false;
    const Vec2 q = front.pos;
    const double lambda = 0.5 * chord;
    const Vec2 u = (front.pos - rear.pos) / chord;
    // dR/dsigma at the rear handle: the link's direction against the path's tangent there.
    const double c = dot(u, rear.tangent);
    const double at_rear = lambda * c;
    // Within half a chord of the front handle the first term alone exceeds chord / 2, which
    // is all the search needs to know there (and R may be tiny).
    auto health_at = [&](const Located& p) {
        const Vec2 w = p.pos - q;
        const double r = norm(w);
        if (r < lambda) return chord - r;
        return std::max(chord - r, -lambda * dot(w, p.tangent) / r);
    };
    // Samples piece by piece, evenly in each piece's parameter (which turns the path by about
    // as many radians on the spirals, exactly on the arcs); the rear handle is the first.
    struct Best {
        double value;
        int piece = 0;
        double u = 0.0, u_lo = 0.0, u_hi = 0.0;
    } best{at_rear, rear.place.piece, rear.place.u, rear.place.u, rear.place.u};
    for (int piece = rear.place.piece; piece <= front.place.piece; ++piece) {
        const auto [begin, end] = path.piece_span(piece);
        const double u0 = piece == rear.place.piece ? rear.place.u : begin;
        const double u1 = piece == front.place.piece ? front.place.u : end;
        const int n = std::clamp(static_cast<int>(std::ceil(std::abs(u1 - u0) / kSampleTurn)), 4, kMaxSamples);
        for (int j = piece == rear.place.piece ? 1 : 0; j <= n; ++j) {
            const double uj = j == n ? u1 : u0 + (u1 - u0) * j / n;
            const double v = health_at(path.at({piece, uj}));
            if (v < best.value) {
                const double a = u0 + (u1 - u0) * std::max(j - 1, 0) / n, b = u0 + (u1 - u0) * std::min(j + 1, n) / n;
                best = {v, piece, uj, std::min(a, b), std::max(a, b)};
            }
        }
    }
    double u_at = best.u, refined = best.value;
    if (best.u_hi > best.u_lo)
        std::tie(u_at, refined) =
            golden_min([&](double x) { return health_at(path.at({best.piece, x})); }, best.u_lo, best.u_hi, kHealthArc);
    out.margin = std::min({best.value, refined, at_rear});
    out.at_root = at_rear <= refined;
    const Place watch = out.at_root ? rear.place : Place{best.piece, u_at};
    out.watch_arc = path.arc(watch);
    if (!(c > 0.0) || !(out.margin > 0.0) || !std::isfinite(vf) || !std::isfinite(vr)) {
        out.margin = std::max(out.margin, 0.0);
        out.step = 0.0;
        return out;
    }
    // How fast the health changes now, exactly, where it is least; a tenth of the worst-case
    // rates below on top covers a least point that moves or a rate that grows over the step.
    //  - At the rear handle it is lambda c, c = T_r . u: T_r turns at kr vr, u at the link's
    //    turn rate w = (u x (vf T_f - vr T_r)) / chord. Near a vanishing root vr grows as 1 / c,
    //    so the steps shrink as c^2, in proportion to the time left.
    //  - At a fixed place between the handles: |dR/dt| <= |vf| and lambda |d(dR/dsigma)/dt|
    //    <= lambda |vf| / R <= |vf| (R >= lambda); at the rear end the root moves at vr and the
    //    places it uncovers have a health of at least lambda (c - |d2R/dsigma2| |vr| tau) -
    //    |vf| tau, |d2R/dsigma2| <= 1 / chord + |kr|.
    const Vec2 qdot = vf * front.tangent;
    const double worst_end = lambda * (1.0 / chord + std::abs(kr)) * std::abs(vr) + std::abs(vf);
    double rate = 0.0;
    if (out.at_root) {
        const double w = cross(u, qdot - vr * rear.tangent) / chord;
        const double cdot = kr * vr * dot(perp(rear.tangent), u) + w * dot(rear.tangent, perp(u));
        rate = lambda * std::abs(cdot) + 0.1 * worst_end;
    } else {
        const Located p = path.at(watch);
        const Vec2 e = normalized(p.pos - q);
        const double r = distance(p.pos, q);
        const double drift_far = std::abs(dot(e, qdot));
        const double drift_slope = lambda * std::abs(dot(qdot, p.tangent) - dot(e, qdot) * dot(e, p.tangent)) / r;
        rate = std::max(drift_far, drift_slope) + 0.1 * std::max(std::abs(vf), worst_end);
    }
    out.step = out.margin / (kSafety * rate);
    return out;
}

}  // namespace

std::optional<Tangency> watch_tangency(const Path& path, const Vec2& q, double chord, double seed, double window) {
    const double a = std::max(path.s_min(), seed - window), b = std::min(path.s_max(), seed + window);
    if (!(b > a)) return std::nullopt;
    // f = (P - q) . T = R dR/ds: a local maximum of R is where f falls through zero.
    auto f = [&](double s) {
        const Located p = path.at_arc(s);
        return dot(p.pos - q, p.tangent);
    };
    constexpr int kSamples = 32;
    double best_lo = NAN, best_hi = NAN, best_distance = INFINITY, f_lo = 0.0, f_hi = 0.0;
    double x0 = a, f0 = f(a);
    for (int j = 1; j <= kSamples; ++j) {
        const double x1 = j == kSamples ? b : a + (b - a) * j / kSamples;
        const double f1 = f(x1);
        if (f0 > 0.0 && f1 <= 0.0) {
            const double distance = seed < x0 ? x0 - seed : seed > x1 ? seed - x1 : 0.0;
            if (distance < best_distance) best_distance = distance, best_lo = x0, best_hi = x1, f_lo = f0, f_hi = f1;
        }
        x0 = x1, f0 = f1;
    }
    if (!std::isfinite(best_distance)) return std::nullopt;
    // Regula falsi (Illinois) on the bracket: f is smooth through a nondegenerate maximum.
    double lo = best_lo, hi = best_hi;
    int side = 0;
    for (int it = 0; it < 100 && hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * (1.0 + std::abs(hi)); ++it) {
        double x = lo + f_lo * (hi - lo) / (f_lo - f_hi);
        if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
        const double fx = f(x);
        if (fx > 0.0) {
            lo = x, f_lo = fx;
            if (side == +1) f_hi *= 0.5;
            side = +1;
        } else {
            hi = x, f_hi = fx;
            if (side == -1) f_lo *= 0.5;
            side = -1;
        }
    }
    const double s = std::abs(f_lo) < std::abs(f_hi) ? lo : hi;
    const Located p = path.at_arc(s);
    const Vec2 w = p.pos - q;
    const double r = norm(w);
    if (!(r > 0.0)) return std::nullopt;
    return Tangency{s, r - chord, p.pos, w / r};
}

}  // namespace dragon::jam
