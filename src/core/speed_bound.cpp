// An upper bound on every handle's speed ratio over a stretch of head travel (speed_bound.hpp).
#include "speed_bound.hpp"
#include "gentle_link.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dragon/geometry.hpp"
#include "dragon/portable_math.hpp"

namespace dragon::speed {

namespace {

// A closed interval of reals, lo <= hi, and the few operations the bound needs. Rounding is
// to nearest: the bound uses these only for the slope L, whose relative error of a few ulps
// moves the bound by ~1e-16 of L h (section 10.1's floating-point model).
struct Iv {
    double lo, hi;
};
Iv operator+(Iv a, Iv b) { return {a.lo + b.lo, a.hi + b.hi}; }
Iv operator-(Iv a, Iv b) { return {a.lo - b.hi, a.hi - b.lo}; }
Iv operator*(Iv a, Iv b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
Iv operator*(double k, Iv a) { return k >= 0 ? Iv{k * a.lo, k * a.hi} : Iv{k * a.hi, k * a.lo}; }
// b strictly positive.
Iv operator/(Iv a, Iv b) {
    const double p[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
Iv hull(Iv a, double x) { return {std::min(a.lo, x), std::max(a.hi, x)}; }
double magnitude(Iv a) { return std::max(std::abs(a.lo), std::abs(a.hi)); }

// The signed curvature over the arc between arc positions of two chains' handle i (rear: the
// lesser): the hull of its values at the two places and at both sides of every join between
// (curvature is monotone along each piece of both paths: constant on an arc, its magnitude
// monotone in theta on a spiral).
Iv curvature_over(const Path& path, const Place& rear, double k_rear, const Place& front, double k_front) {
    Iv k{std::min(k_rear, k_front), std::max(k_rear, k_front)};
    for (int piece = rear.piece; piece < front.piece; ++piece) {
        const auto [begin, end] = path.piece_span(piece);
        if (piece > rear.piece) k = hull(k, path.curvature({piece, begin}));
        k = hull(k, path.curvature({piece, end}));
        k = hull(k, path.curvature({piece + 1, path.piece_span(piece + 1).first}));
    }
    return k;
}

constexpr double kUlp = 0x1p-52;

using gentle::at_or_ahead;

// Handle i's way from chain c0 to chain c1: false if it ends behind where it began; else the
// curvature over it, its turning (the integral of |kappa|) and an upper bound on its length:
// turning / min |kappa| (no arc length, whose inverse hyperbolic sine on a spiral costs more
// than the rest of a bound), or the arc positions' difference where the curvature changes sign.
bool travel(const Path& path, const ChainFacts& c0, const ChainFacts& c1, size_t i, double& length, double& turning, Iv& kappa) {
    const Place& p0 = c0.place[i];
    const Place& p1 = c1.place[i];
    if (!at_or_ahead(path, p1, p0)) return false;
    kappa = curvature_over(path, p0, c0.kappa[i], p1, c1.kappa[i]);
    turning = path.turning(p0, p1);
    const double least = kappa.lo > 0.0 ? kappa.lo : kappa.hi < 0.0 ? -kappa.hi : 0.0;
    // Rounding: the quotient's few ulps, far inside the slack the angles carry.
    length = least > 0.0 ? turning / least * (1.0 + 4.0 * kUlp) : path.arc(p1) - path.arc(p0);
    return true;
}

// The angle from unit u to unit t, in (-pi, pi].
double angle_from(const Vec2& u, const Vec2& t) { return math::atan2(cross(u, t), dot(u, t)); }

}  // namespace

double ratio_error(const Frame& f, int handle) {
    double sensitivity = 0.0;
    for (int i = 0; i < handle; ++i) {
        const Handle& front = f.handles[static_cast<size_t>(i)];
        const Handle& rear = f.handles[static_cast<size_t>(i) + 1];
        const Vec2 u = (front.pos - rear.pos).normalized();
        sensitivity += std::abs(math::tan(angle_from(u, front.tangent))) + std::abs(math::tan(angle_from(u, rear.tangent)));
    }
    return kAngleError * sensitivity + 8.0 * handle * kUlp;
}

void gather(const Path& path, const Frame& f, ChainFacts& out) {
    const size_t n = f.handles.size();
    out.head_arc = f.head_arc;
    out.place.resize(n);
    out.kappa.resize(n);
    out.speed.resize(n);
    out.cos_a.resize(n - 1);
    out.sin_a.resize(n - 1);
    out.cos_b.resize(n - 1);
    out.sin_b.resize(n - 1);
    for (size_t i = 0; i < n; ++i) {
        const Handle& h = f.handles[i];
        out.place[i] = h.place;
        out.kappa[i] = path.curvature(h.place);
        out.speed[i] = h.speed;
        if (i + 1 == n) break;
        const Handle& rear = f.handles[i + 1];
        const Vec2 u = (h.pos - rear.pos).normalized();
        out.cos_a[i] = dot(u, h.tangent);
        out.sin_a[i] = cross(u, h.tangent);
        out.cos_b[i] = dot(u, rear.tangent);
        out.sin_b[i] = cross(u, rear.tangent);
    }
}

namespace {

// cos and sin over a0 + t, |t| <= w, for any a0 (c = cos a0, s = sin a0): c cos t lies between
// c and c (1 - w^2/2), and |s sin t| <= |s| min(w, 1).
Iv cos_any(double c, double s, double w) {
    const double k = c * (1.0 - 0.5 * w * w), q = std::abs(s) * std::min(w, 1.0);
    return {std::max(-1.0, std::min(c, k) - q), std::min(1.0, std::max(c, k) + q)};
}
Iv sin_any(double c, double s, double w) {
    const double k = s * (1.0 - 0.5 * w * w), q = std::abs(c) * std::min(w, 1.0);
    return {std::max(-1.0, std::min(s, k) - q), std::min(1.0, std::max(s, k) + q)};
}

// Where a handle may be over the stretch: the arc between two places, the largest distance
// along the path from its place at the stretch's start (and from its place at the end), the
// turning and curvature over that arc, and whether the handle moves forward all the way (then
// the arc is exactly from its start place to its end place).
struct Reach {
    Place lo, hi;
    double from_start = 0.0, from_end = 0.0;  // m
    double turning = 0.0;                     // rad
    Iv kappa{0.0, 0.0};                       // 1/m
    bool forward = true;
};

// The reach of a handle known to lie between arc positions lo and hi (lo <= hi), at s0 and s1 at
// the stretch's ends.
Reach reach_between(const Path& path, double lo, double hi, double s0, double s1) {
    Reach r;
    r.lo = path.at_arc(lo).place;
    r.hi = path.at_arc(hi).place;
    r.from_start = std::max(s0 - lo, hi - s0);
    r.from_end = std::max(s1 - lo, hi - s1);
    r.turning = path.turning(r.lo, r.hi);
    r.kappa = curvature_over(path, r.lo, path.curvature(r.lo), r.hi, path.curvature(r.hi));
    r.forward = false;
    return r;
}

// dimensionless: the longest link behind a handle, over the handle's least radius, for which
// Lemma C holds: 2 asin(0.38) = 0.78 rad of polar angle, at most twice that of turning (theta +
// atan(theta) grows at most twice as fast as theta), 1.559 rad, below pi/2. (The exact limit is
// 2 sin(pi/8) = 0.765; the margin is far above the rounding of rho = b theta.)
constexpr double kCalmChord = 0.76;

// Lemma C over a stretch: whether no handle behind handle j (its speed within v over the
// stretch, at head speed 1) can move faster than it, anywhere in the stretch. Handle j moves
// forward all the way (v above 0), so it stays at or behind its place at the stretch's end, c1's,
// where calm_at() judges the rest.
bool calm_behind(const Path& path, const BenchSpec& spec, const ChainFacts& c1, size_t j, Iv v) {
    return v.lo > 0.0 && calm_at(path, spec, c1.place[j], j);
}

}  // namespace

bool calm_at(const Path& path, const BenchSpec& spec, const Place& place, size_t j) {
    const Spiral* spiral = path.coil_in_spiral(place);
    if (!spiral) return false;
    const double rho = spiral->b() * place.u;  // m
    const int n = spec.handle_count();
    if (static_cast<int>(j) + 1 >= n) return true;  // the tail's rear handle: none behind
    // m: the longest link behind handle j (the head's, from handle 0; a body's after it).
    const double longest = std::max(spec.link_after(static_cast<int>(j)), spec.link_after(n - 2));
    return longest <= kCalmChord * rho;
}

size_t first_calm_handle(const Path& path, const BenchSpec& spec, const Frame& f) {
    for (size_t j = 0; j < f.handles.size(); ++j)
        if (f.handles[j].speed > 0.0 && calm_at(path, spec, f.handles[j].place, j)) return j;
    return f.handles.size();
}

StretchBound bound_stretch(const Path& path, const BenchSpec& spec, const ChainFacts& c0, const ChainFacts& c1,
                           std::vector<HandleArc>* arcs) {
    StretchBound out;
    if (arcs) arcs->clear();
    // The handles both chains hold: all of them, or as many as the shorter holds. Without
    // `arcs` the bound is on every handle's speed, so chains cut short (as Q5's scan cuts them,
    // up to a calm handle) must reach a calm tail (fail below); with `arcs` it is on the handles
    // given (a contact search's leading benches: the tail behind them is apart by its own proof).
    const size_t n = std::min(c0.place.size(), c1.place.size());
    const bool whole = arcs || static_cast<int>(n) == spec.handle_count();
    const double h = c1.head_arc - c0.head_arc;
    const auto fail = [&out](size_t handle) {
        out.verdict = BoundVerdict::not_monotone;
        out.handle = static_cast<int>(handle);
        return out;
    };
    // cos of an angle must stay above this for Lemma A (the angle within pi/2 - kAngleMargin).
    const double least_cos = std::sin(kAngleMargin);
    // Handle i's speed (head speed 1) and its slope in head travel over the stretch: the slope
    // of log v while every handle so far moves forward (`logs`), else of v itself.
    Iv v{1.0, 1.0}, dlog{0.0, 0.0}, dv{0.0, 0.0};
    bool logs = true;
    double sensitivity = 0.0;  // sum of |tan alpha| + |tan beta| over the links so far (while logs)
    double error = 0.0;        // bound on the error of the computed end speeds of handle i (kAngleError's model)
    out.upper = 1.0;           // the head
    out.handle = 0;
    Reach front;
    front.lo = c0.place[0];
    front.hi = c1.place[0];
    {
        double moved = 0.0;
        if (!travel(path, c0, c1, 0, moved, front.turning, front.kappa)) return fail(0);
        front.from_start = front.from_end = moved;
    }
    if (arcs) arcs->push_back({front.lo, front.hi, front.turning});
    // Without `arcs` (which wants every handle's), the bound stops at a calm tail (Lemma C).
    if (!arcs && calm_behind(path, spec, c1, 0, v)) return out;
    for (size_t i = 0; i + 1 < n; ++i) {
        const double d = spec.link_after(static_cast<int>(i));
        const double ca0 = c0.cos_a[i], sa0 = c0.sin_a[i], cb0 = c0.cos_b[i], sb0 = c0.sin_b[i];
        const double va = c0.speed[i + 1], vb = c1.speed[i + 1];
        Reach rear;
        double moved_rear = 0.0;
        // Lemma A: the front moving forward, the rear ending ahead and both angles below pi/2
        // over the box: the rear moves forward on the arc between its two places.
        bool forward = logs && front.forward && va > 0.0 && vb > 0.0 && ca0 > 0.0 && cb0 > 0.0 &&
                       travel(path, c0, c1, i + 1, moved_rear, rear.turning, rear.kappa);
        Iv ca{0, 0}, cb{0, 0}, sa{0, 0}, sb{0, 0};
        const auto angles = [&](const Reach& r) {
            // The link's turning: each end within its reach's distance of its place at the start.
            const double y = 0.5 * (front.from_start + r.from_start) / d;
            if (!(y < 0.5)) return false;
            const double link_turn = 2.0 * y / std::sqrt(1.0 - y * y);
            const double wa = front.turning + link_turn + kAngleSlack, wb = r.turning + link_turn + kAngleSlack;
            ca = cos_any(ca0, sa0, wa);
            sa = sin_any(ca0, sa0, wa);
            cb = cos_any(cb0, sb0, wb);
            sb = sin_any(cb0, sb0, wb);
            return cb.lo > least_cos;
        };
        if (forward) {
            rear.lo = c0.place[i + 1];
            rear.hi = c1.place[i + 1];
            rear.from_start = rear.from_end = moved_rear;
            forward = angles(rear) && ca.lo > least_cos;
        }
        if (!forward) {
            // Lemma A': the rear handle's map F (rear place from front place) has
            // |F'| = |cos alpha| / cos beta <= G while the rear stays in a candidate arc R; if
            // F's value at the start, give or take G times the front's reach, lies inside R, the
            // rear never leaves it (a first exit would have to come within that distance), and it
            // is within G times the front's reaches of both its end places.
            const double m = path.arc(c0.place[i + 1]), M = path.arc(c1.place[i + 1]);
            if (!std::isfinite(m) || !std::isfinite(M)) return fail(i + 1);
            double guess = 2.0 * front.from_start * std::max(std::abs(ca0 / cb0), std::abs(c1.cos_a[i] / c1.cos_b[i])) + 1e-9;
            bool found = false;
            for (int round = 0; round < 6 && !found; ++round) {
                if (!(std::min(m, M) - guess > path.s_min() && std::max(m, M) + guess < path.s_max())) return fail(i + 1);
                rear = reach_between(path, std::min(m, M) - guess, std::max(m, M) + guess, m, M);
                if (!angles(rear)) return fail(i + 1);
                const double slope = magnitude(ca) / cb.lo;
                const double lo = std::max(m - slope * front.from_start, M - slope * front.from_end);
                const double hi = std::min(m + slope * front.from_start, M + slope * front.from_end);
                // A first exit from R would come within slope * reach of m: inside R, so none.
                if (m - slope * front.from_start > std::min(m, M) - guess && m + slope * front.from_start < std::max(m, M) + guess) {
                    // The angles above stand (the candidate holds the rear); the next link starts
                    // from the tighter arc just proved.
                    found = true;
                    rear = reach_between(path, std::min({lo, m, M}), std::max({hi, m, M}), m, M);
                } else {
                    guess = 2.0 * std::max(std::min(m, M) - (m - slope * front.from_start), m + slope * front.from_start - std::max(m, M));
                }
            }
            if (!found) return fail(i + 1);
        }
        const Iv g = ca / cb;
        // delta = alpha - beta: the tangents' angle; the link's own turning cancels in it.
        const double sd0 = std::abs(sa0 * cb0 - ca0 * sb0);
        const double wd = front.turning + rear.turning + 2.0 * kAngleSlack;
        const Iv sd2{sd0 > wd ? (sd0 - wd) * (sd0 - wd) : 0.0, std::min(1.0, (sd0 + wd) * (sd0 + wd))};
        const Iv product = v * g;
        if (forward) {
            // g' / g = v E: E = -tan(alpha) kappa_i + tan(beta) kappa_{i+1} g + sin^2(delta) / (d cos(alpha) cos^2(beta)).
            const Iv ta = sa / ca, tb = sb / cb;
            const Iv e = (Iv{0.0, 0.0} - ta * front.kappa) + tb * rear.kappa * g + (1.0 / d) * (sd2 / (ca * cb * cb));
            // (log v_{i+1})' = (log v_i)' + v_i E: the slopes of the logs add link by link (the
            // products of the factors g would multiply their enclosures' widths instead).
            dlog = dlog + v * e;
            sensitivity += magnitude(ta) + magnitude(tb);
            error = (kAngleError * sensitivity + 8.0 * static_cast<double>(i + 1) * kUlp) * magnitude(product);
        } else {
            // g' = v H, H = -sin(alpha) kappa_i / cos(beta) + kappa_{i+1} sin(beta) cos^2(alpha) / cos^3(beta)
            //            + sin^2(delta) / (d cos^3(beta)), with no cos(alpha) below the line;
            // v_{i+1}' = v_i' g + v_i^2 H.
            const Iv cb3 = cb * cb * cb;
            const Iv hh = (Iv{0.0, 0.0} - sa * front.kappa / cb) + rear.kappa * sb * ca * ca / cb3 + (1.0 / d) * (sd2 / cb3);
            dv = (logs ? v * dlog : dv) * g + v * v * hh;
            logs = false;
            // The computed speed's error, absolute now (|tan alpha| is unbounded where the rear
            // stops): the front's carried by |g|, and each angle's kAngleError moving g by at most
            // (|sin alpha| + |g| |sin beta|) / cos beta of it; a few ulps of rounding.
            error = error * magnitude(g) + magnitude(v) * kAngleError * (magnitude(sa) + magnitude(g) * magnitude(sb)) / cb.lo +
                    8.0 * kUlp * magnitude(product);
        }
        // The rear speed lies in v g; and (Lipschitz, slope at most L) within L h / 2 of its
        // ends' mean, give or take their computed values' error; L from the one enclosure, then
        // again from the tighter one.
        Iv speed_now = product;
        double top = INFINITY;
        const double mean = 0.5 * (va + vb);
        for (int round = 0; round < 2; ++round) {
            const double slope = logs ? magnitude(speed_now * dlog) : magnitude(dv);
            top = std::min(top, std::abs(mean) + 0.5 * slope * h + error);
            const Iv lipschitz{mean - 0.5 * slope * h - error, mean + 0.5 * slope * h + error};
            const Iv both{std::max(speed_now.lo, lipschitz.lo), std::min(speed_now.hi, lipschitz.hi)};
            if (both.lo > both.hi) break;  // empty only by rounding: keep the wider
            speed_now = both;
        }
        if (!(top < INFINITY)) return fail(i + 1);  // the slope's enclosure overflowed: a shorter stretch may do
        if (top > out.upper) {
            out.upper = top;
            out.handle = static_cast<int>(i + 1);
        }
        v = speed_now;
        if (!arcs && calm_behind(path, spec, c1, i + 1, v)) return out;
        rear.forward = forward;
        if (arcs) arcs->push_back({rear.lo, rear.hi, rear.turning});
        front = rear;
    }
    // Chains cut short of the whole: the handles behind them are bounded by nothing here.
    if (!whole) return fail(n);
    return out;
}

}  // namespace dragon::speed
