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
// For an angle interval inside (-pi/2, pi/2): cos rises to 1 at 0 and falls after, sin and tan rise.
Iv cos_of(Iv a) {
    const double c0 = math::cos(a.lo), c1 = math::cos(a.hi);
    return {std::min(c0, c1), a.lo <= 0.0 && a.hi >= 0.0 ? 1.0 : std::max(c0, c1)};
}
Iv sin_of(Iv a) { return {math::sin(a.lo), math::sin(a.hi)}; }
Iv tan_of(Iv a) { return {math::tan(a.lo), math::tan(a.hi)}; }

// The signed curvature over the arc from place `rear` to place `front`: the hull of its values
// at the ends of each piece's part (curvature is monotone along each piece of both paths: constant on
// an arc, its magnitude monotone in theta on a spiral), both sides of every join taken.
Iv curvature_over(const Path& path, const Place& rear, const Place& front) {
    Iv k{INFINITY, -INFINITY};
    for (int piece = rear.piece; piece <= front.piece; ++piece) {
        const auto [begin, end] = path.piece_span(piece);
        const double a = piece == rear.piece ? rear.u : begin;
        const double b = piece == front.piece ? front.u : end;
        k = hull(hull(k, path.curvature({piece, a})), path.curvature({piece, b}));
    }
    return k;
}

// The angle from unit u to unit t, in (-pi, pi].
double angle_from(const Vec2& u, const Vec2& t) { return math::atan2(cross(u, t), dot(u, t)); }

constexpr double kUlp = 0x1p-52;

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

StretchBound bound_stretch(const Path& path, const BenchSpec& spec, const Frame& f0, const Frame& f1,
                           BoundWorkspace& ws) {
    StretchBound out;
    const size_t n = f0.handles.size();
    const double h = f1.head_arc - f0.head_arc;
    ws.arc0.resize(n);
    ws.arc1.resize(n);
    for (size_t i = 0; i < n; ++i) {
        ws.arc0[i] = path.arc(f0.handles[i].place);
        ws.arc1[i] = path.arc(f1.handles[i].place);
        if (ws.arc1[i] < ws.arc0[i]) {  // Lemma A's premise: every handle ends no further back
            out.verdict = BoundVerdict::not_monotone;
            out.handle = static_cast<int>(i);
            return out;
        }
    }
    constexpr double kRight = 0.5 * std::numbers::pi - kAngleMargin;
    // Handle i's speed (head speed 1) and its slope in head travel, over the stretch.
    Iv v{1.0, 1.0}, dv{0.0, 0.0};
    double sensitivity = 0.0;  // sum of |tan alpha| + |tan beta| over the links so far
    out.upper = 1.0;  // the head
    out.handle = 0;
    double turn_front = path.turning(f0.handles[0].place, f1.handles[0].place);
    Iv kappa_front = curvature_over(path, f0.handles[0].place, f1.handles[0].place);
    for (size_t i = 0; i + 1 < n; ++i) {
        const Handle& front = f0.handles[i];
        const Handle& rear = f0.handles[i + 1];
        const double d = spec.link_after(static_cast<int>(i));
        const double turn_rear = path.turning(rear.place, f1.handles[i + 1].place);
        const Iv kappa_rear = curvature_over(path, rear.place, f1.handles[i + 1].place);
        // The link's turning over the stretch: both ends move at most their arcs' lengths.
        const double moved = (ws.arc1[i] - ws.arc0[i]) + (ws.arc1[i + 1] - ws.arc0[i + 1]);
        if (!(moved < 2.0 * d)) {
            out.verdict = BoundVerdict::not_monotone;
            out.handle = static_cast<int>(i + 1);
            return out;
        }
        const double link_turn = 2.0 * math::asin(moved / (2.0 * d));
        const Vec2 u = (front.pos - rear.pos).normalized();
        const double a0 = angle_from(u, front.tangent), b0 = angle_from(u, rear.tangent);
        const double wa = turn_front + link_turn + kAngleSlack, wb = turn_rear + link_turn + kAngleSlack;
        const Iv alpha{a0 - wa, a0 + wa}, beta{b0 - wb, b0 + wb};
        if (!(alpha.lo > -kRight && alpha.hi < kRight && beta.lo > -kRight && beta.hi < kRight)) {
            out.verdict = BoundVerdict::not_monotone;
            out.handle = static_cast<int>(i + 1);
            return out;
        }
        const Iv ca = cos_of(alpha), cb = cos_of(beta);
        const Iv g = ca / cb;
        Iv v_rear = v * g;
        // The rear speed also lies within its values at the ends and the slope bound of the last
        // round (kept below); the enclosure from g alone grows link by link.
        const Iv dpsi = (1.0 / d) * (v * sin_of(alpha) - v_rear * sin_of(beta));
        const Iv dalpha = kappa_front * v - dpsi, dbeta = kappa_rear * v_rear - dpsi;
        const Iv dg = g * ((Iv{0.0, 0.0} - tan_of(alpha) * dalpha) + tan_of(beta) * dbeta);
        dv = dv * g + v * dg;
        const double slope = magnitude(dv);
        const double va = f0.handles[i + 1].speed, vb = f1.handles[i + 1].speed;
        sensitivity += magnitude(tan_of(alpha)) + magnitude(tan_of(beta));
        const double error = kAngleError * sensitivity + 8.0 * static_cast<double>(i + 1) * kUlp;
        const double top = 0.5 * (va + vb + slope * h) + 0.5 * (va + vb) * error;
        if (top > out.upper) {
            out.upper = top;
            out.handle = static_cast<int>(i + 1);
        }
        // Lipschitz: v_rear lies within [max(va, vb) ... ] less slope * h / 2 below and above.
        const Iv lipschitz{0.5 * (va + vb - slope * h) - 0.5 * (va + vb) * error, top};
        const Iv both{std::max(v_rear.lo, lipschitz.lo), std::min(v_rear.hi, lipschitz.hi)};
        v = both.lo <= both.hi ? both : v_rear;  // empty only by rounding: keep the wider
        turn_front = turn_rear;
        kappa_front = kappa_rear;
    }
    return out;
}

}  // namespace dragon::speed
