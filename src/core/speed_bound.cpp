// An upper bound on every handle's speed ratio over a stretch of head travel (speed_bound.hpp).
#include "speed_bound.hpp"

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

// cos and sin over the angles a0 + t, |t| <= w, from c = cos a0 >= 0 and s = sin a0, by Taylor
// with remainder (cos t >= 1 - t^2/2, |sin t| <= |t|): no trigonometry per stretch.
Iv cos_near(double c, double s, double w) { return {c - std::abs(s) * w - 0.5 * w * w, std::min(1.0, c + std::abs(s) * w)}; }
Iv sin_near(double c, double s, double w) {
    const double spread = 0.5 * std::abs(s) * w * w + c * w;
    return {std::max(-1.0, s - spread), std::min(1.0, s + spread)};
}

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

// Whether place `a` is at or ahead of place `b` on the path (further in the direction of travel).
bool at_or_ahead(const Path& path, const Place& a, const Place& b) {
    if (a.piece != b.piece) return a.piece > b.piece;
    const auto [begin, end] = path.piece_span(a.piece);
    return end > begin ? a.u >= b.u : a.u <= b.u;
}

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

StretchBound bound_stretch(const Path& path, const BenchSpec& spec, const ChainFacts& c0, const ChainFacts& c1) {
    StretchBound out;
    const size_t n = c0.place.size();
    const double h = c1.head_arc - c0.head_arc;
    const auto fail = [&out](size_t handle) {
        out.verdict = BoundVerdict::not_monotone;
        out.handle = static_cast<int>(handle);
        return out;
    };
    // cos of an angle must stay above this for Lemma A (the angle within pi/2 - kAngleMargin).
    const double least_cos = std::sin(kAngleMargin);
    // Handle i's speed (head speed 1) and its slope in head travel, over the stretch.
    Iv v{1.0, 1.0}, dlog{0.0, 0.0};
    double sensitivity = 0.0;  // sum of |tan alpha| + |tan beta| over the links so far
    out.upper = 1.0;           // the head
    out.handle = 0;
    // Handle i's arc over the stretch: its length (an upper bound), the curvature and turning on it.
    double moved_front = 0.0, turn_front = 0.0;
    Iv kappa_front{0.0, 0.0};
    if (!travel(path, c0, c1, 0, moved_front, turn_front, kappa_front)) return fail(0);
    for (size_t i = 1; i < n; ++i) {
        if (!(c0.speed[i] > 0.0 && c1.speed[i] > 0.0)) {
            out.verdict = BoundVerdict::backs_up;
            out.handle = static_cast<int>(i);
            return out;
        }
    }
    for (size_t i = 0; i + 1 < n; ++i) {
        const double d = spec.link_after(static_cast<int>(i));
        double moved_rear = 0.0, turn_rear = 0.0;
        Iv kappa_rear{0.0, 0.0};
        // Lemma A's premise: each handle ends no further back than it began.
        if (!travel(path, c0, c1, i + 1, moved_rear, turn_rear, kappa_rear)) return fail(i + 1);
        // The link's turning over the stretch: both ends move at most their arcs' lengths, so it
        // is at most 2 asin(y), y = moved / 2d, and asin(y) <= y / sqrt(1 - y^2).
        const double y = 0.5 * (moved_front + moved_rear) / d;
        if (!(y < 0.5)) return fail(i + 1);
        const double link_turn = 2.0 * y / std::sqrt(1.0 - y * y);
        const double wa = turn_front + link_turn + kAngleSlack, wb = turn_rear + link_turn + kAngleSlack;
        const double ca0 = c0.cos_a[i], sa0 = c0.sin_a[i], cb0 = c0.cos_b[i], sb0 = c0.sin_b[i];
        if (!(ca0 > 0.0 && cb0 > 0.0)) return fail(i + 1);
        const Iv ca = cos_near(ca0, sa0, wa), cb = cos_near(cb0, sb0, wb);
        if (!(ca.lo > least_cos && cb.lo > least_cos)) return fail(i + 1);
        const Iv sa = sin_near(ca0, sa0, wa), sb = sin_near(cb0, sb0, wb);
        const Iv ta = sa / ca, tb = sb / cb;
        // delta = alpha - beta: the tangents' angle; the link's own turning cancels in it.
        const double sd0 = std::abs(sa0 * cb0 - ca0 * sb0);
        const double wd = turn_front + turn_rear + 2.0 * kAngleSlack;
        const Iv sd2{sd0 > wd ? (sd0 - wd) * (sd0 - wd) : 0.0, std::min(1.0, (sd0 + wd) * (sd0 + wd))};
        const Iv g = ca / cb;
        // g' / g = v E: E = -tan(alpha) kappa_i + tan(beta) kappa_{i+1} g + sin^2(delta) / (d cos(alpha) cos^2(beta)).
        const Iv e = (Iv{0.0, 0.0} - ta * kappa_front) + tb * kappa_rear * g + (1.0 / d) * (sd2 / (ca * cb * cb));
        // (log v_{i+1})' = (log v_i)' + v_i E: the slopes of the logs add link by link (the
        // products of the factors g would multiply their enclosures' widths instead).
        dlog = dlog + v * e;
        const double va = c0.speed[i + 1], vb = c1.speed[i + 1];
        sensitivity += magnitude(ta) + magnitude(tb);
        const double error = kAngleError * sensitivity + 8.0 * static_cast<double>(i + 1) * kUlp;
        // The rear speed lies in v g; and (Lipschitz, slope at most L) within L h / 2 of its
        // ends' mean; L from the one enclosure, then again from the tighter one.
        const Iv product = v * g;
        Iv rear = product;
        double top = INFINITY;
        for (int round = 0; round < 2; ++round) {
            const double slope = magnitude(rear * dlog);
            top = std::min(top, 0.5 * (va + vb + slope * h) + 0.5 * (va + vb) * error);
            const Iv lipschitz{0.5 * (va + vb - slope * h) - 0.5 * (va + vb) * error, top};
            const Iv both{std::max(rear.lo, lipschitz.lo), std::min(rear.hi, lipschitz.hi)};
            if (both.lo > both.hi) break;  // empty only by rounding: keep the wider
            rear = both;
        }
        if (!(top < INFINITY)) return fail(i + 1);  // the slope's enclosure overflowed: a shorter stretch may do
        if (top > out.upper) {
            out.upper = top;
            out.handle = static_cast<int>(i + 1);
        }
        v = rear;
        moved_front = moved_rear;
        turn_front = turn_rear;
        kappa_front = kappa_rear;
    }
    return out;
}

}  // namespace dragon::speed
