// Proof that a step of the chain's motion holds no contact (swept_proof.hpp).
#include "swept_proof.hpp"
#include "gentle_link.hpp"
#include "handle_accel.hpp"
#include "shape_rates.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>

#include "speed_bound.hpp"
#include "untouched_tail.hpp"
#include "dragon/collision.hpp"
#include "dragon/constants.hpp"
#include "dragon/geometry.hpp"
#include "dragon/portable_math.hpp"

namespace dragon::contact {

namespace {

using gentle::at_or_ahead;

// The projections of an enclosure's hull points on n: least and largest.
void project(const SweptWorkspace::Swept& s, const Vec2& n, double& lo, double& hi) {
    lo = INFINITY;
    hi = -INFINITY;
    for (size_t q = 0; q < s.count; ++q) {
        const double p = dot(s.v[q], n);
        lo = std::min(lo, p);
        hi = std::max(hi, p);
    }
}

using HandleSpan = SweptWorkspace::HandleSpan;

// An enclosure's bounding box: its hull points' extent, dilated by its radius and half the
// box margin (two boxes that do not meet are then more than kProofBoxMargin apart).
void set_box(SweptWorkspace::Swept& s) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (size_t q = 0; q < s.count; ++q) {
        const Vec2& v = s.v[q];
        x0 = std::min(x0, v.x());
        x1 = std::max(x1, v.x());
        y0 = std::min(y0, v.y());
        y1 = std::max(y1, v.y());
    }
    const double grow = s.radius + 0.5 * kProofBoxMargin;
    s.x0 = x0 - grow, s.x1 = x1 + grow, s.y0 = y0 - grow, s.y1 = y1 + grow;
}

// The enclosure of a board (its rectangle `r`, the link `d` between its handles) whose front
// handle lies in `F` and rear handle in `R`: the 16 combinations of their chords' ends in each
// corner's linear form, and the radius the dilations add.
void enclose(const Rect& r, double d, const HandleSpan& F, const HandleSpan& R, SweptWorkspace::Swept& s) {
    s.radius = 0.0;
    s.count = 16;
    size_t q = 0;
    const Vec2 fs[2] = {F.p0, F.p1}, rs[2] = {R.p0, R.p1};
    for (const double along : {-1.0, 1.0}) {
        for (const double across : {-1.0, 1.0}) {
            const double cF = 0.5 + along * r.half_length / d;
            const double cR = 0.5 - along * r.half_length / d;
            const double j = across * r.half_width / d;
            for (const Vec2& f : fs)
                for (const Vec2& b : rs) s.v[q++] = cF * f + cR * b + j * perp(f - b);
            s.radius = std::max(s.radius, math::hypot(cF, j) * F.dilation + math::hypot(cR, j) * R.dilation);
        }
    }
    set_box(s);
}


// Benches a < b (0-based), b >= a + 2, of the chain near each other along it: a lower bound on
// their distance at every moment of the step that holds without enclosing them, or -inf. With
// u the unit chord from bench b's front handle (handle b) to bench a's rear handle (handle
// a + 1), at distance D, bench a's points project on u no lower than its rear handle's
// projection less e cos(phi_a) + w |sin(phi_a)| (e: its overhang beyond the handle, w: its half
// width, phi_a: the angle between its axis and u, while below pi/2), and bench b's no higher
// than its front handle's plus the same of its own; so they are at least
//     D - e_a - e_b - w_a sin(tau_a) - w_b sin(tau_b)
// apart, tau bounding phi. Every chord of an arc points within the arc's tangent range, so
// phi_a is at most the turning of the path from handle b to handle a (bench a's arc and the
// middle one), phi_b from handle b + 1 to handle a + 1, and each link between them makes an
// angle at most the middle arc's turning tau_m with u: D >= cos(tau_m) times their lengths
// (exactly the one link's length when b = a + 2). Over the step every arc lies between its rear
// handle's place at the start and its front handle's at the end (the handles move forward).
template <class Turning>
double chain_gap(const Turning& turning, const BenchSpec& spec, const Frame& f0, size_t a, size_t b) {
    const double tau_a = turning(b, a);          // handle b (front of b) to handle a (front of a)
    const double tau_b = turning(b + 1, a + 1);  // rear of b to rear of a
    const double tau_m = turning(b, a + 1);      // the links between
    constexpr double kRight = 0.5 * std::numbers::pi;
    if (!(tau_a < kRight && tau_b < kRight && tau_m < kRight)) return -INFINITY;
    double links = 0.0;
    for (size_t k = a + 1; k < b; ++k) links += spec.link_length(static_cast<int>(k) + 1);
    const double chord = b == a + 2 ? links : links * math::cos(tau_m);
    const Rect& ra = f0.benches[a];
    const Rect& rb = f0.benches[b];
    const double ea = ra.half_length - 0.5 * spec.link_length(static_cast<int>(a) + 1);
    const double eb = rb.half_length - 0.5 * spec.link_length(static_cast<int>(b) + 1);
    return chord - ea - eb - ra.half_width * math::sin(tau_a) - rb.half_width * math::sin(tau_b);
}

}  // namespace

namespace {

// No pair is taken as apart before its enclosures are looked at (prove_step's proofs).
constexpr auto kNotSeparately = [](size_t, size_t) { return false; };
// Relative: the offsets' bounds are widened by this (bench_reach's own slack is 1e-9 of them;
// this one covers the rounding of the radii passed to it, a few ulps).
constexpr double kOffsetSlack = 1e-9;

// (cos, sin) of an angle: how a frame turned by it is undone.
Vec2 turn_of(double angle) { return {math::cos(angle), math::sin(angle)}; }

// v, a vector of the fixed frame, in the frame turned by the angle whose (cos, sin) is `turn`.
Vec2 turned_by(const Vec2& v, const Vec2& turn) {
    const double c = turn.x(), sn = turn.y();
    return Vec2{c * v.x() + sn * v.y(), -sn * v.x() + c * v.y()};
}

// The unit vector from the centre to handle i of f: on the plain spiral (cos, sin) of its polar
// angle, to rounding.
Vec2 direction(const Frame& f, size_t i) { return f.handles[i].pos / norm(f.handles[i].pos); }

// The product of two (cos, sin) pairs: that of the sum of their angles.
Vec2 times(const Vec2& u, const Vec2& v) { return {u.x() * v.x() - u.y() * v.y(), u.x() * v.y() + u.y() * v.x()}; }

// Every bench's enclosures on the spiral (ws.benches, one set of nb per corner, from set
// `first` on): bench k's handles at polar offsets D from the head between their values in fa and
// fb, its link's span between its two values, the spiral's b and the head's angle T those of
// each corner.
void enclose_on_spiral(const BenchSpec& spec, const Frame& fa, const Frame& fb, std::span<const SpiralCorner> corners,
                       SweptWorkspace& ws, size_t first = 0) {
    const size_t nb = std::min(fa.benches.size(), fb.benches.size());
    ws.benches.resize((first + corners.size()) * nb);
    ws.directions.resize(6 * nb);
    const Vec2 head_a = direction(fa, 0), head_b = direction(fb, 0);  // the heads' (cos, sin)
    for (size_t t = 0; t < corners.size(); ++t) {
        const double T = corners[t].T, b = corners[t].b;
        for (size_t k = 0; k < nb; ++k) {
            // Bench k: its front handle at D in [d_lo, d_hi], its link's span alpha in
            // [a_lo, a_hi]; the corners over that box are within the hull of their values at
            // its four corners (bilinear interpolation) plus the interpolation's error,
            // dD^2 / 8 max|c_DD| + da^2 / 8 max|c_aa|, where |P''| <= r + 2b for
            // P(D) = b (T + D) (cos D, sin D).
            const Place& front0 = fa.handles[k].place;
            const Place& front1 = fb.handles[k].place;
            const double d0 = front0.u - fa.handles[0].place.u, d1 = front1.u - fb.handles[0].place.u;
            const double a0 = fa.handles[k + 1].place.u - front0.u, a1 = fb.handles[k + 1].place.u - front1.u;
            const double d_lo = std::min(d0, d1), d_hi = std::max(d0, d1);
            const double a_lo = std::min(a0, a1), a_hi = std::max(a0, a1);
            const Rect& r = fa.benches[k];
            const double link = spec.link_length(static_cast<int>(k) + 1);
            const double r_max = b * (T + d_hi + a_hi) + 2.0 * b;  // bounds |P''| on the box
            SweptWorkspace::Swept& sw = ws.benches[(first + t) * nb + k];
            Vec2 Fs[4], Rs[4];  // the handles at the box's four corners (D, alpha)
            Vec2* const e = &ws.directions[6 * k];  // their directions, the same at every corner
            if (t == 0) {
                // (cos, sin) of D and of D + alpha at the box's corners, from the handles' points
                // (on the spiral each at its polar angle): no sine or cosine, whose argument
                // reduction cost a tenth of Q2's proof.
                const Vec2 front_a = direction(fa, k), front_b = direction(fb, k);
                const Vec2 D0 = turned_by(front_a, head_a), D1 = turned_by(front_b, head_b);
                const Vec2 A0 = turned_by(direction(fa, k + 1), front_a);
                const Vec2 A1 = turned_by(direction(fb, k + 1), front_b);
                Vec2* w = e;
                w[0] = d0 <= d1 ? D0 : D1;
                w[1] = d0 <= d1 ? D1 : D0;
                const Vec2& lo = a0 <= a1 ? A0 : A1;
                const Vec2& hi = a0 <= a1 ? A1 : A0;
                for (size_t c = 0; c < 4; ++c) w[2 + c] = times(w[c < 2 ? 0 : 1], c % 2 == 0 ? lo : hi);
            }
            for (size_t c = 0; c < 4; ++c) {
                const double D = c < 2 ? d_lo : d_hi, A = c % 2 == 0 ? a_lo : a_hi;
                Fs[c] = b * (T + D) * e[c < 2 ? 0 : 1];
                Rs[c] = b * (T + D + A) * e[2 + c];
            }
            size_t q = 0;
            double worst = 0.0;
            for (const double along : {-1.0, 1.0}) {
                for (const double across : {-1.0, 1.0}) {
                    const double cF = 0.5 + along * r.half_length / link;
                    const double cR = 0.5 - along * r.half_length / link;
                    const double j = across * r.half_width / link;
                    for (size_t c = 0; c < 4; ++c) sw.v[q++] = cF * Fs[c] + cR * Rs[c] + j * perp(Fs[c] - Rs[c]);
                    const double dd = (d_hi - d_lo), da = (a_hi - a_lo);
                    worst = std::max(worst, (dd * dd * (std::abs(cF) + std::abs(cR) + 2.0 * std::abs(j)) +
                                             da * da * (std::abs(cR) + std::abs(j))) * r_max / 8.0);
                }
            }
            sw.radius = worst;
            sw.count = 16;
            set_box(sw);
        }
    }
}

// The second-order enclosures: two ends `h` apart (m of head travel, or of head radius in a
// cell), each with `per_end` sets of enclosures (ws.benches' sets [e per_end, (e + 1) per_end)
// are end e's), and the chains whose boards give each end's axes, turned into the enclosures'
// frame by -angle, turn[e] = (cos, sin) of that angle (the head's in a turned frame; (1, 0) in
// the fixed one).
struct Rotating {
    double h;
    size_t per_end;
    const Frame* axes[2];
    Vec2 turn[2];
};

// A lower bound on the distance of benches a and b (0-based) at every moment of a step from
// their enclosures at its two ends (`rot`; each set a bench's places at that end for one value
// of what else varies, within the set's hull dilated by its radius) and their bounds
// (ws.corner_accel, ws.corner_speed: over the step each corner's |c''| and |c'|). For unit axes
// n0 (at the start) and n1 (at the end) let n(x) turn from n0 to n1 at the constant rate
// psi' = psi / h; with o a fixed point, q(x) = (c(x) - o) . n(x) has
// q'' = c'' . n + 2 c' . n' + (c - o) . n'', so |q''| <= |c''| + 2 |c'| |psi'| + |c - o| psi'^2,
// and q lies within h^2 / 8 of that of the chord between its end values. The gap of the two
// benches along n(x) is the least over their corners of such differences: at least the least of
// the end gaps (each set's, less its radii), less each bench's h^2 / 8 max|q''|. The axes: each
// board's two edge directions at each end (the same edge at both), and the two ends' exact
// separation axes. Stops at the first axis whose bound exceeds `enough` (m: a sharper one is not
// needed).
double rotating_pair_gap(const Rotating& rot, size_t nb, size_t a, size_t b, const SweptWorkspace& ws, double enough) {
    const double h = rot.h;
    const size_t sets = 2 * rot.per_end;
    const auto set = [&](size_t t, size_t k) -> const SweptWorkspace::Swept& { return ws.benches[t * nb + k]; };
    // o: the middle of the two benches' first enclosures.
    Vec2 o = Vec2::Zero();
    for (const size_t k : {a, b})
        for (size_t q = 0; q < set(0, k).count; ++q) o += set(0, k).v[q];
    o /= static_cast<double>(set(0, a).count + set(0, b).count);
    // Each bench's corners' greatest distance from o over the step.
    double reach[2];
    for (size_t m = 0; m < 2; ++m) {
        const size_t k = m == 0 ? a : b;
        double far = 0.0;
        for (size_t t = 0; t < sets; ++t)
            for (size_t q = 0; q < set(t, k).count; ++q) far = std::max(far, norm(set(t, k).v[q] - o) + set(t, k).radius);
        reach[m] = far + 0.5 * h * ws.corner_speed[k];
    }
    double best = -INFINITY;
    const auto try_axes = [&](const Vec2& n0, Vec2 n1) {
        if (dot(n0, n1) < 0.0) n1 = -n1;  // the same orientation at both ends
        // The angle between them (below pi/2) is at most its tangent.
        const double rate = std::abs(cross(n0, n1)) / dot(n0, n1) / h;
        double above = INFINITY, below = INFINITY;
        for (size_t t = 0; t < sets; ++t) {
            const Vec2& n = t < rot.per_end ? n0 : n1;
            double alo, ahi, blo, bhi;
            project(set(t, a), n, alo, ahi);
            project(set(t, b), n, blo, bhi);
            const double radii = set(t, a).radius + set(t, b).radius;
            above = std::min(above, blo - ahi - radii);
            below = std::min(below, alo - bhi - radii);
        }
        double loss = 0.0;
        for (size_t m = 0; m < 2; ++m) {
            const size_t k = m == 0 ? a : b;
            loss += 0.125 * h * h * (ws.corner_accel[k] + 2.0 * ws.corner_speed[k] * rate + reach[m] * rate * rate);
        }
        best = std::max(best, std::max(above, below) - loss);
    };
    // A vector of end e's chain turned into the enclosures' frame.
    const auto turned = [&](const Vec2& v, size_t e) { return turned_by(v, rot.turn[e]); };
    const Frame& f0 = *rot.axes[0];
    const Frame& f1 = *rot.axes[1];
    const Rect* boards[4] = {&f0.benches[a], &f0.benches[b], &f1.benches[a], &f1.benches[b]};
    for (size_t m = 0; m < 2 && best <= enough; ++m) {
        try_axes(turned(perp(boards[m]->axis), 0), turned(perp(boards[2 + m]->axis), 1));
        if (best > enough) break;
        try_axes(turned(boards[m]->axis, 0), turned(boards[2 + m]->axis, 1));
    }
    if (best <= enough)
        try_axes(turned(separation(f0.benches[a], f0.benches[b]).axis, 0),
                 turned(separation(f1.benches[a], f1.benches[b]).axis, 1));
    return best;
}

// Whether any two non-adjacent benches' enclosures (ws.benches: `frames` sets of nb, made
// from the frames fa and fb) may meet, pair by pair: proved apart by chain_gap() with
// `turning`, or along one of the boards' edge normals in fa and fb (turned by each one's head
// angle when `turned`), at every frame's enclosures; each farther apart than `apart_by`.
// (`apart` proves a pair only apart, so it goes with apart_by = 0: kNotSeparately otherwise.)
// With `rotating` (the second-order enclosures: `frames` sets, half at each of the step's two
// ends) each axis is a pair, one at each end, turning at a constant rate between them:
// rotating_pair_gap().
template <class Turning, class Apart>
StepProof separate_enclosures(const BenchSpec& spec, const Frame& fa, const Frame& fb, size_t frames, bool turned,
                              const Turning& turning, const Apart& apart, SweptWorkspace& ws, double apart_by = 0.0,
                              const Rotating* rotating = nullptr) {
    StepProof out;
    const size_t nb = std::min(fa.benches.size(), fb.benches.size());
    // What a pair must be proved apart by, and the boxes' margin: two boxes that do not meet
    // are more than `margin` apart, at least apart_by.
    const double required = apart_by + kProofSlack;
    const double margin = std::max(kProofBoxMargin, required);
    const double grow = 0.5 * (margin - kProofBoxMargin);
    // Boxes: each bench's over its enclosures.
    ws.boxes.resize(nb);
    for (size_t k = 0; k < nb; ++k) {
        SweptWorkspace::Swept box = ws.benches[k];
        for (size_t t = 1; t < frames; ++t) {
            const SweptWorkspace::Swept& o = ws.benches[t * nb + k];
            box.x0 = std::min(box.x0, o.x0), box.x1 = std::max(box.x1, o.x1);
            box.y0 = std::min(box.y0, o.y0), box.y1 = std::max(box.y1, o.y1);
            box.radius = std::max(box.radius, o.radius);
        }
        ws.boxes[k] = {box.x0 - grow, box.x1 + grow, box.y0 - grow, box.y1 + grow, box.radius};
    }
    // The frames' axes into the turned one, each by its own head's -theta_0.
    Vec2 turn[2] = {Vec2{1.0, 0.0}, Vec2{1.0, 0.0}};
    if (turned) turn[0] = turn_of(fa.handles[0].place.u), turn[1] = turn_of(fb.handles[0].place.u);
    const auto turn_back = [&](const Vec2& v, size_t e) { return turned_by(v, turn[e]); };
    // Pairs whose boxes (grown by half the margin each) meet: sweep and prune along x. Every
    // other pair's boxes are more than `margin` apart in x or y, so are its benches.
    ws.order.resize(nb);
    for (size_t k = 0; k < nb; ++k) ws.order[k] = static_cast<int>(k);
    std::sort(ws.order.begin(), ws.order.end(),
              [&](int a, int b) { return ws.boxes[static_cast<size_t>(a)].x0 < ws.boxes[static_cast<size_t>(b)].x0; });
    ws.active.clear();
    out.least_gap = margin;
    for (const int k : ws.order) {
        const SweptWorkspace::Box& s = ws.boxes[static_cast<size_t>(k)];
        size_t keep = 0;
        for (const int m : ws.active)
            if (ws.boxes[static_cast<size_t>(m)].x1 >= s.x0) ws.active[keep++] = m;
        ws.active.resize(keep);
        for (const int m : ws.active) {
            if (std::abs(m - k) < 2) continue;  // neighbours share a handle: never a contact
            const SweptWorkspace::Box& o = ws.boxes[static_cast<size_t>(m)];
            if (o.y1 < s.y0 || s.y1 < o.y0) continue;
            const size_t a = static_cast<size_t>(std::min(k, m)), b = static_cast<size_t>(std::max(k, m));
            if (apart(a, b)) continue;
            const double radii = o.radius + s.radius;
            double proved = b >= a + 2 ? chain_gap(turning, spec, fa, a, b) : -INFINITY;
            if (!(proved > required) && rotating) {
                proved = std::max(proved, rotating_pair_gap(*rotating, nb, a, b, ws, margin));
            } else if (!(proved > required)) {
                // The boards' edge normals in both frames (in the turned frame there). The
                // normals first: the long sides face each other in most near pairs, and the
                // loop stops at the first axis that proves the pair.
                std::array<Vec2, 8> axes = {perp(fa.benches[a].axis), perp(fa.benches[b].axis), perp(fb.benches[a].axis),
                                            perp(fb.benches[b].axis), fa.benches[a].axis, fa.benches[b].axis,
                                            fb.benches[a].axis, fb.benches[b].axis};
                if (turned)
                    for (size_t q = 0; q < axes.size(); ++q) axes[q] = turn_back(axes[q], (q / 2) % 2);
                double best = -INFINITY;
                const auto try_axis = [&](const Vec2& n) {
                    // b beyond a along n, and a beyond b: each the least over the enclosures
                    // (every frame: concave in the frames' parameters, each side on its own).
                    double above = INFINITY, below = INFINITY;
                    for (size_t t = 0; t < frames; ++t) {
                        double alo, ahi, blo, bhi;
                        project(ws.benches[t * nb + a], n, alo, ahi);
                        project(ws.benches[t * nb + b], n, blo, bhi);
                        above = std::min(above, blo - ahi);
                        below = std::min(below, alo - bhi);
                    }
                    best = std::max({best, above, below});
                };
                for (const Vec2& n : axes) {
                    try_axis(n);
                    if (best > radii + margin) break;  // enough: a sharper bound is not needed
                }
                if (!(best - radii > required)) {
                    // Where the boards' nearest points are corner to corner no edge normal is
                    // the direction between them, and each falls short of their distance: the
                    // exact separation's axis in each frame is.
                    for (size_t e = 0; e < 2; ++e) {
                        const Frame& fe = e == 0 ? fa : fb;
                        const Vec2 n = separation(fe.benches[a], fe.benches[b]).axis;
                        try_axis(turned ? turn_back(n, e) : n);
                    }
                }
                proved = best - radii;
            }
            if (!(proved > required))
                return {StepVerdict::too_close, proved, static_cast<int>(a) + 1, static_cast<int>(b) + 1};
            if (proved < out.least_gap) {
                out.least_gap = proved;
                out.bench_a = static_cast<int>(a) + 1;
                out.bench_b = static_cast<int>(b) + 1;
            }
        }
        ws.active.push_back(k);
    }
    return out;
}

// Each bench's bounds over its corners from its handles' (ws.accel, ws.speed): a corner
// c = cF F + cR R + j perp(F - R) has |c''| <= hypot(cF, j) |F''| + hypot(cR, j) |R''|, and |c'|
// the same with the speeds (ws.corner_accel, ws.corner_speed).
void corner_bounds(const BenchSpec& spec, const Frame& f, size_t nb, SweptWorkspace& ws) {
    ws.corner_accel.resize(nb);
    ws.corner_speed.resize(nb);
    for (size_t k = 0; k < nb; ++k) {
        const double d = spec.link_length(static_cast<int>(k) + 1);
        const Rect& r = f.benches[k];
        double worst = 0.0, fastest = 0.0;  // over the corners: |c''| and |c'|
        for (const double along : {-1.0, 1.0}) {
            const double cF = 0.5 + along * r.half_length / d, cR = 0.5 - along * r.half_length / d;
            const double j = r.half_width / d;
            // (cF I + j perp) scales every vector by hypot(cF, j); sqrt is exact to rounding.
            const double front = std::sqrt(cF * cF + j * j), rear = std::sqrt(cR * cR + j * j);
            worst = std::max(worst, front * ws.accel[k] + rear * ws.accel[k + 1]);
            fastest = std::max(fastest, front * ws.speed[k] + rear * ws.speed[k + 1]);
        }
        ws.corner_accel[k] = worst;
        ws.corner_speed[k] = fastest;
    }
}

// Grows each bench's enclosures' boxes (`sets` sets of nb) by h^2 / 8 times its corners' bound on
// |c''|: every corner lies, at each moment of the step, within that of the point a fraction of
// the way between its two end places that the moment is of the step, so the bench within the
// box of both ends' enclosures grown by it (the broad phase; rotating_pair_gap bounds each pair
// near enough to look at).
void grow_boxes(size_t sets, size_t nb, double h, SweptWorkspace& ws) {
    for (size_t t = 0; t < sets; ++t)
        for (size_t k = 0; k < nb; ++k) {
            SweptWorkspace::Swept& sw = ws.benches[t * nb + k];
            const double by = 0.125 * h * h * ws.corner_accel[k];
            sw.x0 -= by, sw.x1 += by, sw.y0 -= by, sw.y1 += by;
        }
}

// A board's enclosure at one moment: its four corners exactly (geometry.hpp's corners), turned
// by the angle whose (cos, sin) is `turn` ((1, 0): the fixed frame).
void exact_enclosure(const Rect& r, const Vec2& turn, SweptWorkspace::Swept& sw) {
    const Corners c = corners(r);
    for (size_t q = 0; q < 4; ++q) sw.v[q] = turned_by(c.p[q], turn);
    sw.count = 4;
    sw.radius = 0.0;
    set_box(sw);
}

// Each bench's enclosures at the step's two ends (ws.benches: nb at the start, nb at the end):
// its four corners there, exactly (ws.accel, ws.speed: each handle's bounds in head travel).
void enclose_second_order(const BenchSpec& spec, const Frame& f0, const Frame& f1, double h, SweptWorkspace& ws) {
    const size_t nb = std::min(f0.benches.size(), f1.benches.size());
    ws.benches.resize(2 * nb);
    corner_bounds(spec, f0, nb, ws);
    for (size_t t = 0; t < 2; ++t)
        for (size_t k = 0; k < nb; ++k) exact_enclosure((t == 0 ? f0 : f1).benches[k], Vec2{1.0, 0.0}, ws.benches[t * nb + k]);
    grow_boxes(2, nb, h, ws);
}

// A step where a handle may stop or back up, or a link turn by a quarter turn or more (the
// turnaround's tight arcs): Proposition 1 does not hold, but the speed bounds of Q5's proof do
// (core/speed_bound.hpp, Lemmas A and A'): each handle lies, for the whole step, on an arc of the
// path between two places, from the chain at the step's two ends and the rigid-link relation.
// Each bench is then enclosed from its handles' arcs (each within L min(tau, 2) / 4 of its chord,
// Proposition 2) as a forward step's are, and the pairs separated in the fixed frame.
StepProof prove_by_speed_bounds(const Path& path, const BenchSpec& spec, const Frame& f0, const Frame& f1,
                                SweptWorkspace& ws, double apart_by) {
    const size_t nb = std::min(f0.benches.size(), f1.benches.size());
    speed::gather(path, f0, ws.facts0);
    speed::gather(path, f1, ws.facts1);
    const speed::StretchBound bound = speed::bound_stretch(path, spec, ws.facts0, ws.facts1, &ws.arcs);
    if (bound.verdict != speed::BoundVerdict::bounded || ws.arcs.size() < nb + 1)
        return {StepVerdict::not_monotone, INFINITY, bound.handle, 0};
    ws.spans.resize(nb + 1);
    for (size_t i = 0; i <= nb; ++i) {
        const speed::HandleArc& a = ws.arcs[i];
        const double length = std::abs(path.arc(a.hi) - path.arc(a.lo));
        ws.spans[i] = {path.at(a.lo).pos, path.at(a.hi).pos, length * std::min(a.turning, 2.0) / 4.0};
    }
    ws.benches.resize(nb);
    for (size_t k = 0; k < nb; ++k)
        enclose(f0.benches[k], spec.link_length(static_cast<int>(k) + 1), ws.spans[k], ws.spans[k + 1], ws.benches[k]);
    // No chain-neighbour bound here (its turnings assume handles moving forward): enclosures only.
    const auto no_turning = [](size_t, size_t) { return INFINITY; };
    return separate_enclosures(spec, f0, f1, 1, false, no_turning, kNotSeparately, ws, apart_by);
}

// A cell's second order (prove_spiral_cell_second_order), proved also `apart_by` (m); with
// `reach_known`, ws.reach holds every bench's offsets from the spiral over the cell
// (spiral_cell_benches) and pairs they keep apart are not looked at.
StepProof cell_second_order(const BenchSpec& spec, const SpiralCell& cell, SweptWorkspace& ws, bool reach_known,
                            double apart_by);

// Whether a step of the motion on the spiral of parameter b (m/rad), from f0 to f1 (every handle
// on it at both ends), is a cell of one pitch: the head's angle falls from f0's to f1's, and the
// cell's bounds hold in f1, the chain with the largest spans and the least radii.
bool step_is_spiral_cell(const Frame& f0, const Frame& f1, double b) {
    if (!(f1.handles[0].place.u < f0.handles[0].place.u)) return false;
    for (size_t m = 0; m + 1 < f1.handles.size(); ++m)
        if (!link_keeps_cell_bounds(f1.handles[m].place.u, f1.handles[m + 1].place.u, b, b)) return false;
    return true;
}

}  // namespace

StepProof prove_step(const Path& path, const BenchSpec& spec, const Frame& f0, const Frame& f1, SweptWorkspace& ws,
                     double apart_by, Enclosures which) {
    StepProof out;
    const size_t nb = std::min(f0.benches.size(), f1.benches.size());
    const size_t nh = nb + 1;
    if (nb < 3) return out;
    // On the spiral (every handle on it at both ends), the turning between two places is the
    // change of the tangent's angle theta + atan(theta): kept for each handle at both ends.
    const auto* spiral = dynamic_cast<const Spiral*>(&path);
    bool turned = spiral != nullptr;
    for (size_t i = 0; turned && i < nh; ++i)
        turned = f0.handles[i].place.piece == 0 && f1.handles[i].place.piece == 0;
    // 0. The second order in the frame turned with the head, on the spiral (swept_proof.hpp,
    // item 6): a step of the motion there is a cell of one pitch (pitch_proof.hpp), the head's
    // radius falling from f0's to f1's, when the cell's bounds hold at its inner end f1 (every
    // link's span below a quarter turn, its front's radius above b tan(span / 2)): every chain
    // of the step is then the chain at some head radius between the two, and
    // prove_spiral_cell_second_order's proof (methods.md 8.1, Propositions P5 and P6) holds for
    // it. In that frame the chain's common turning is gone: each corner moves and bends only as
    // the chain's shape changes, near the head some 25 times slower than in the fixed frame at
    // Q2's contact (b / r0 as far per metre of travel), so it proves steps there about three
    // times as long as the fixed frame's second order (3b below). No handle need move forward
    // for it, so it is tried before item 1's conditions.
    const auto second_order_turned = [&]() -> StepProof {
        const double b = spiral->b();
        const double r1 = b * f1.handles[0].place.u, r0 = b * f0.handles[0].place.u;
        const SpiralCell cell{f1, f1, f0, f0, r1, r0, b, b};
        StepProof p = cell_second_order(spec, cell, ws, false, apart_by);
        p.second_order = true;
        return p;
    };
    // A cell's step is proved by it or not at all: the other enclosures (items 1-3) proved none of
    // the 126 steps it failed on (too long, or near a contact) in the first-contact searches at
    // pitches 0.45, 0.5 and 0.55 m, and a failed try costs about as much as a proof.
    const bool cell = turned && step_is_spiral_cell(f0, f1, spiral->b());
    if (cell && which != Enclosures::first_order && which != Enclosures::second_order) return second_order_turned();
    if (which == Enclosures::second_order_turned) return {StepVerdict::not_monotone, -INFINITY, 0, 0};
    ws.arc0.resize(nh);  // the tangent's angle at the start (spiral only)
    ws.arc1.resize(nh);  // and at the end
    if (turned)
        for (size_t i = 0; i < nh; ++i) {
            ws.arc0[i] = Spiral::tangent_angle(f0.handles[i].place.u);
            ws.arc1[i] = Spiral::tangent_angle(f1.handles[i].place.u);
        }
    // The turning of the path from handle `rear`'s place at the start to handle `front`'s at the end.
    const auto turning = [&](size_t rear, size_t front) {
        return turned ? ws.arc0[rear] - ws.arc1[front] : path.turning(f0.handles[rear].place, f1.handles[front].place);
    };
    // 1. Every handle moves forward, and every link's hull over the step turns by less than
    // pi/2 (the induction of swept_proof.hpp, from the head, whose travel is forward).
    ws.dilation.resize(nh);
    ws.hull.resize(nh - 1);
    ws.own.resize(nh);
    for (size_t i = 0; i < nh; ++i) {
        const Place& p0 = f0.handles[i].place;
        const Place& p1 = f1.handles[i].place;
        if (!at_or_ahead(path, p1, p0)) return prove_by_speed_bounds(path, spec, f0, f1, ws, apart_by);
        if (i + 1 < nh) {
            // The link from handle i to handle i + 1 lies, over the step, between handle i + 1's
            // place at the start and handle i's at the end.
            ws.hull[i] = turning(i + 1, i);
            if (!gentle::hull_turns_gently(path, p1, f0.handles[i + 1].place, ws.hull[i]))
                return prove_by_speed_bounds(path, spec, f0, f1, ws, apart_by);
        }
        // 2. The handle's arc over the step, within `dilation` of its chord (the fixed frame's
        // enclosures only), and how far the path turns along it.
        ws.own[i] = turned ? std::abs(ws.arc0[i] - ws.arc1[i]) : path.turning(p0, p1);
        if (!turned) {
            const double length = std::abs(path.arc(p1) - path.arc(p0));
            ws.dilation[i] = length * std::min(ws.own[i], 2.0) / 4.0;
        }
    }
    // 3. Each bench's enclosure, in one of two ways; a step either proves is proved.
    // (a) First order: on the spiral r = b theta the benches are enclosed in the frame turned
    // with the head (by -theta_0), where the chain's motion is only its slow change of shape:
    // each link's polar span alpha_m = theta_{m+1} - theta_m is a decreasing function of its
    // front handle's theta while below pi (implicit differentiation of
    // |P(theta + alpha) - P(theta)|^2 = d^2), so it grows monotonically over the step, and
    // D_i = theta_i - theta_0 lies between its two end values. Handle i is then at
    // b (theta_0 + D_i) (cos D_i, sin D_i): linear in theta_0, an arc of a spiral in D_i. For each
    // end value T of theta_0 the benches are enclosed over their D intervals (enclose_on_spiral);
    // a pair's projected gap on a fixed axis is, for fixed D's, concave in theta_0 (the least of
    // linear functions less the largest), so it is least at one of the two ends T: the pair is
    // apart when it is apart at both. Elsewhere (the turnaround) the enclosures are in the fixed
    // frame, from the handles' arcs (item 2 above). Their looseness grows with the step's
    // length: right for long steps between benches far apart.
    const auto first_order = [&] {
        if (turned) {
            const double b = spiral->b();
            const std::array<SpiralCorner, 2> corners{{{f1.handles[0].place.u, b}, {f0.handles[0].place.u, b}}};
            enclose_on_spiral(spec, f0, f1, corners, ws);
            return separate_enclosures(spec, f0, f1, corners.size(), true, turning, kNotSeparately, ws, apart_by);
        }
        ws.benches.resize(nb);
        for (size_t k = 0; k < nb; ++k)
            enclose(f0.benches[k], spec.link_length(static_cast<int>(k) + 1),
                    {f0.handles[k].pos, f1.handles[k].pos, ws.dilation[k]},
                    {f0.handles[k + 1].pos, f1.handles[k + 1].pos, ws.dilation[k + 1]}, ws.benches[k]);
        return separate_enclosures(spec, f0, f1, 1, false, turning, kNotSeparately, ws, apart_by);
    };
    // (b) Second order: each corner within h^2 / 8 max|c''| of the chord between its end places
    // at every moment (handle_accel.hpp bounds c''), a pair's gap along axes that turn with the
    // boards between the ends at least the lesser of its end gaps less that (rotating_pair_gap):
    // its looseness falls with the step's square, right for short steps near a contact. (On a
    // cell of the spiral the turned frame's, item 0, proves every step of the contest's Q2 this
    // one does, and more.)
    const auto second_order = [&]() -> std::optional<StepProof> {
        if (!handle_accel_bounds(path, spec, f0, f1, ws.hull, ws.own, ws.accel, ws.speed)) return std::nullopt;
        const double h = std::abs(f1.head_arc - f0.head_arc);
        enclose_second_order(spec, f0, f1, h, ws);
        const Rotating rotating{h, 1, {&f0, &f1}, {Vec2{1.0, 0.0}, Vec2{1.0, 0.0}}};
        StepProof proof = separate_enclosures(spec, f0, f1, 2, false, turning, kNotSeparately, ws, apart_by, &rotating);
        proof.second_order = true;
        return proof;
    };
    if (which == Enclosures::first_order) return first_order();
    if (which == Enclosures::either_first_order_first) {
        const StepProof first = first_order();
        if (first.verdict == StepVerdict::proved) return first;
        if (const std::optional<StepProof> second = second_order(); second && second->verdict == StepVerdict::proved)
            return *second;
        return first;
    }
    const std::optional<StepProof> second = second_order();
    if (which == Enclosures::second_order) return second.value_or(StepProof{StepVerdict::too_close, -INFINITY, 0, 0});
    if (second && second->verdict == StepVerdict::proved) return *second;
    return first_order();
}

namespace {

// Benches i < j kept apart over a cell by their offsets from the spiral (as in untouched_tail.hpp,
// whose bench_reach bounds them): at pitch p a point shared by the two has unwrapped angles 2 pi m
// apart, and offsets rho - b psi differing by p m; each bench's offsets lie in [-in, out].
// `closest` and `farthest` bound, over the cell, the angle from bench i's rear handle to bench
// j's front handle and from bench i's front handle to bench j's rear one; every whole turn m the
// angle spans (each widened by its reach) allow must be one the least pitch keeps them apart by.
bool offsets_apart(double closest, double farthest, const std::optional<BenchReach>& ri,
                   const std::optional<BenchReach>& rj, double pitch_lo) {
    if (!ri || !rj) return false;
    const double spread = ri->angle + rj->angle;
    const double m_lo = std::ceil((closest - spread) / kTwoPi), m_hi = std::floor((farthest + spread) / kTwoPi);
    // m = 0 never is such a turn; m > 0 is when p m > out_i + in_j, m < 0 when p |m| > in_i +
    // out_j (the least |m| each way decides).
    if (m_lo > m_hi) return true;  // their angle spans never meet, a whole number of turns apart
    if (m_lo <= 0.0 && m_hi >= 0.0) return false;
    const double m = m_lo > 0.0 ? m_lo : -m_hi;
    const double reach = (m_lo > 0.0 ? ri->out + rj->in : ri->in + rj->out) * (1.0 + kOffsetSlack);
    return pitch_lo * m > reach + kProofSlack;
}

}  // namespace

size_t spiral_cell_benches(const BenchSpec& spec, const std::vector<double>& theta_a, const std::vector<double>& theta_b,
                           double b_lo, double b_hi, SweptWorkspace& ws) {
    const size_t nb = std::min(theta_a.size(), theta_b.size()) - 1;
    // Each bench's offsets from the spiral anywhere in the cell: from its least radii (theta_b at
    // b_lo: every radius rises with r0 and b), its link's least span (theta_a) and the largest b
    // (the bounds grow with b).
    ws.reach.resize(nb);
    double widest = 0.0;  // rad: the largest reach in angle
    double most_in = 0.0, most_out = 0.0;  // m: the largest offsets each way
    for (size_t k = 0; k < nb; ++k) {
        const double rho_front = b_lo * theta_b[k], rho_rear = b_lo * theta_b[k + 1];
        ws.reach[k] = bench_reach(b_hi, spec, static_cast<int>(k) + 1, rho_front / b_hi, rho_rear / b_hi,
                                  theta_a[k + 1] - theta_a[k]);
        if (!ws.reach[k]) return nb;
        widest = std::max(widest, ws.reach[k]->angle);
        if (k > 0) most_in = std::max(most_in, ws.reach[k]->in), most_out = std::max(most_out, ws.reach[k]->out);
    }
    const double pitch_lo = kTwoPi * b_lo;
    // A pitch above every bench's offsets together (the head's board aside: it is longer) keeps
    // any two such benches a whole turn or more apart: only their pairs whose spans may meet on
    // the same turn (m = 0) are left to look at (offsets_apart's test for them decides it for
    // every m), and the head's pairs.
    const bool turns_apart = pitch_lo > (most_in + most_out) * (1.0 + kOffsetSlack) + kProofSlack;
    const double spread = 2.0 * widest;
    const auto D_a = [&](size_t k) { return theta_a[k] - theta_a[0]; };
    const auto D_b = [&](size_t k) { return theta_b[k] - theta_b[0]; };
    // For each bench j and whole turn m, the benches i whose angle spans may meet j's m turns
    // round form a run that only moves on as j does: i_lo (the first with D_a(i + 1) >=
    // D_a(j) - 2 pi m - spread) and i_hi (the last with D_b(i) <= D_b(j + 1) + spread - 2 pi m).
    const double turns = std::floor((D_b(nb) + spread) / kTwoPi);
    size_t watched = 0;  // benches 1..watched hold every pair not proved apart
    for (double m = 0.0; m <= turns; ++m) {
        size_t i_lo = 0, i_hi = 0;  // i_hi: one past the last
        for (size_t j = 2; j < nb; ++j) {
            while (i_lo < nb && D_a(i_lo + 1) < D_a(j) - kTwoPi * m - spread) ++i_lo;
            if (m > 0.0 && turns_apart && i_lo > 0) break;  // none but the head's pairs can meet, and it is behind
            while (i_hi < nb && D_b(i_hi) <= D_b(j + 1) + spread - kTwoPi * m) ++i_hi;
            const size_t last = m > 0.0 && turns_apart ? std::min<size_t>(i_hi, 1) : i_hi;
            for (size_t i = i_lo; i < std::min(last, j - 1); ++i)
                if (!offsets_apart(D_a(j) - D_a(i + 1), D_b(j + 1) - D_b(i), ws.reach[i], ws.reach[j], pitch_lo))
                    watched = std::max(watched, j + 1);
        }
    }
    return watched;
}

namespace {

// A cell's pairs apart (separate_enclosures on ws.benches' `sets` sets): fa and fb are the chains
// with the least and the largest polar offsets, T_min and b_lo the least head angle and b; with
// `reach_known` the pairs ws.reach's offsets keep apart are not looked at; each pair proved more
// than `apart_by` apart.
StepProof separate_cell(const BenchSpec& spec, const Frame& fa, const Frame& fb, double T_min, double b_lo, size_t sets,
                        SweptWorkspace& ws, const Rotating* rotating = nullptr, bool reach_known = true,
                        double apart_by = 0.0) {
    // The turning from handle `rear` to handle `front` anywhere in the cell: the polar span
    // between them, at most its value in fb (every link's span is largest there), plus the
    // change of atan(theta) over it, at most the span over 1 + theta^2 at the front's least theta.
    const double fa0 = fa.handles[0].place.u;
    const auto turning = [&](size_t rear, size_t front) {
        const double span = fb.handles[rear].place.u - fb.handles[front].place.u;
        const double theta = T_min + (fa.handles[front].place.u - fa0);
        return span * (1.0 + 1.0 / (1.0 + theta * theta));
    };
    const double pitch_lo = kTwoPi * b_lo;
    const auto apart = [&](size_t i, size_t j) {
        return reach_known && offsets_apart(fa.handles[j].place.u - fa.handles[i + 1].place.u,
                                            fb.handles[j + 1].place.u - fb.handles[i].place.u, ws.reach[i], ws.reach[j],
                                            pitch_lo);
    };
    return separate_enclosures(spec, fa, fb, sets, true, turning, apart, ws, apart_by, rotating);
}

}  // namespace

StepProof prove_spiral_cell(const BenchSpec& spec, const Frame& fa, const Frame& fb, std::span<const SpiralCorner> corners,
                            SweptWorkspace& ws) {
    enclose_on_spiral(spec, fa, fb, corners, ws);
    double T_min = INFINITY, b_lo = INFINITY;
    for (const SpiralCorner& c : corners) T_min = std::min(T_min, c.T), b_lo = std::min(b_lo, c.b);
    return separate_cell(spec, fa, fb, T_min, b_lo, corners.size(), ws);
}

namespace {

StepProof cell_second_order(const BenchSpec& spec, const SpiralCell& cell, SweptWorkspace& ws, bool reach_known,
                            double apart_by) {
    const Frame& least = cell.outer_hi;  // the least polar offsets: the largest head radius and b
    const Frame& most = cell.inner_lo;   // the largest: the least of both
    if (!shape_rate_bounds(least, most, cell.b_lo, cell.b_hi, ws.speed, ws.accel))
        return {StepVerdict::not_monotone, -INFINITY, 0, 0};
    const size_t nb = std::min({cell.inner_lo.benches.size(), cell.inner_hi.benches.size(), cell.outer_lo.benches.size(),
                                cell.outer_hi.benches.size()});
    corner_bounds(spec, least, nb, ws);
    // Each end's enclosures over the range of b at its head radius (one set when the range is
    // one pitch): for fixed offsets a handle's place (r0 + b D)(cos D, sin D) is linear in b, so
    // a pair's gap along a fixed axis is concave in b, least at one of b's two ends.
    const size_t per_end = cell.b_lo == cell.b_hi ? 1 : 2;
    const Vec2 turn[2] = {turn_of(cell.inner_hi.handles[0].place.u), turn_of(cell.outer_hi.handles[0].place.u)};
    for (size_t e = 0; e < 2; ++e) {
        const Frame& lo = e == 0 ? cell.inner_lo : cell.outer_lo;
        const Frame& hi = e == 0 ? cell.inner_hi : cell.outer_hi;
        if (per_end == 1) {
            // One pitch: each bench's four corners there, exactly, turned with the head.
            ws.benches.resize((e + 1) * nb);
            for (size_t k = 0; k < nb; ++k) exact_enclosure(hi.benches[k], turn[e], ws.benches[e * nb + k]);
            continue;
        }
        const double r = e == 0 ? cell.r_lo : cell.r_hi;
        const std::array<SpiralCorner, 2> corners{{{r / cell.b_hi, cell.b_hi}, {r / cell.b_lo, cell.b_lo}}};
        enclose_on_spiral(spec, hi, lo, corners, ws, e * per_end);
    }
    const double h = cell.r_hi - cell.r_lo;
    grow_boxes(2 * per_end, nb, h, ws);
    // The axes from the chains at b_hi, turned by their heads' angles into the head's frame.
    const Rotating rotating{h, per_end, {&cell.inner_hi, &cell.outer_hi}, {turn[0], turn[1]}};
    return separate_cell(spec, least, most, cell.r_lo / cell.b_hi, cell.b_lo, 2 * per_end, ws, &rotating, reach_known,
                         apart_by);
}

}  // namespace

StepProof prove_spiral_cell_second_order(const BenchSpec& spec, const SpiralCell& cell, SweptWorkspace& ws) {
    return cell_second_order(spec, cell, ws, true, 0.0);
}

}  // namespace dragon::contact
