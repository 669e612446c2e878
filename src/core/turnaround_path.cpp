// The turnaround path: coil-in spiral, arc 1, arc 2, coil-out spiral, and its chord search.
#include <cmath>
#include <limits>
#include <utility>

#include "chord_march.hpp"
#include "dragon/constants.hpp"
#include "dragon/turnaround.hpp"
#include "dragon/portable_math.hpp"

namespace dragon {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A chord root this close (in radians of arc angle) outside an arc's range still counts as on
// it: the root is then at the join, and rounding put it a hair past the piece's end. Both sides
// of a join are searched with this slack, so a root at a join is never missed by both.
constexpr double kJoinSlack = 1e-12;


}  // namespace

TurnaroundPath::TurnaroundPath(const SCurve& design)
    : design_(design), coil_in_(design.pitch), length_at_entry_(coil_in_.length_to(design.entry_theta)) {
    u1_start_ = math::atan2(design_.entry.y() - design_.c1.y(), design_.entry.x() - design_.c1.x());
    u1_end_ = u1_start_ - design_.angle1;
    u2_start_ = math::atan2(design_.c1.y() - design_.c2.y(), design_.c1.x() - design_.c2.x());
    u2_end_ = u2_start_ + design_.angle2;
}

double TurnaroundPath::join_arc(int piece) const {
    switch (piece) {
        case 1: return 0.0;
        case 2: return design_.length1;
        case 3: return design_.length;
        default: return piece <= 0 ? -kInf : kInf;
    }
}

std::pair<double, double> TurnaroundPath::piece_range(int piece) const {
    switch (piece) {
        case 0: return {kInf, design_.entry_theta};
        case 1: return {u1_start_, u1_end_};
        case 2: return {u2_start_, u2_end_};
        default: return {design_.entry_theta, kInf};
    }
}

Located TurnaroundPath::at(Place p) const {
    switch (p.piece) {
        case 0: return coil_in_.at(p);
        case 1: {
            const double c = math::cos(p.u), s = math::sin(p.u);
            return {p, design_.c1 + design_.r1 * Vec2{c, s}, {s, -c}};  // clockwise
        }
        case 2: {
            const double c = math::cos(p.u), s = math::sin(p.u);
            return {p, design_.c2 + design_.r2 * Vec2{c, s}, {-s, c}};  // counter-clockwise
        }
        default: {
            // -P(theta) travelled with theta increasing: the tangent -P'/|P'| is the coil-in one.
            const Located in = coil_in_.at({0, p.u});
            return {p, -in.pos, in.tangent};
        }
    }
}

double TurnaroundPath::arc(Place p) const {
    switch (p.piece) {
        case 0: return length_at_entry_ - coil_in_.length_to(p.u);
        case 1: return design_.r1 * (u1_start_ - p.u);
        case 2: return design_.length1 + design_.r2 * (p.u - u2_start_);
        default: return design_.length + (coil_in_.length_to(p.u) - length_at_entry_);
    }
}

Located TurnaroundPath::at_arc(double s) const {
    if (s < 0.0) return at({0, coil_in_.theta_at_length(length_at_entry_ - s)});
    if (s < design_.length1) return at({1, u1_start_ - s / design_.r1});
    if (s < design_.length) return at({2, u2_start_ + (s - design_.length1) / design_.r2});
    return at({3, coil_in_.theta_at_length(length_at_entry_ + (s - design_.length))});
}

double TurnaroundPath::s_min() const { return -kInf; }
double TurnaroundPath::s_max() const { return kInf; }

double TurnaroundPath::curvature(Place p) const {
    switch (p.piece) {
        case 0: return coil_in_.curvature(p);
        case 1: return -1.0 / design_.r1;
        case 2: return 1.0 / design_.r2;
        // Turned by pi (orientation kept) but travelled the other way: the sign flips.
        default: return -coil_in_.curvature({0, p.u});
    }
}

// Piece by piece from rear to front: the spirals' tangent angle theta + atan(theta) changes
// monotonically along each, and an arc turns by the angle it sweeps.
double TurnaroundPath::turning(Place rear, Place front) const {
    double total = 0.0;
    for (int piece = rear.piece; piece <= front.piece; ++piece) {
        const auto [begin, end] = piece_range(piece);
        const double a = piece == rear.piece ? rear.u : begin;
        const double b = piece == front.piece ? front.u : end;
        if (piece == 1 || piece == 2) total += std::abs(a - b);
        else total += std::abs(Spiral::tangent_angle(a) - Spiral::tangent_angle(b));
    }
    return total;
}

// Along the travel the curvature magnitude rises on the coil-in spiral up to its value at A,
// is 1 / r1 and 1 / r2 on the arcs, and falls from its value at B (the same as at A) on the
// coil-out spiral.
double TurnaroundPath::curvature_bounded_before(double k) const {
    const double at_entry = coil_in_.curvature_at(design_.entry_theta);
    if (at_entry > k) return arc({0, coil_in_.theta_of_curvature(k)});
    if (1.0 / design_.r1 > k) return 0.0;
    if (1.0 / design_.r2 > k) return design_.length1;
    return kInf;
}

double TurnaroundPath::curvature_bounded_after(double k) const {
    const double at_exit = coil_in_.curvature_at(design_.entry_theta);
    if (at_exit > k) return arc({3, coil_in_.theta_of_curvature(k)});
    if (1.0 / design_.r2 > k) return design_.length;
    if (1.0 / design_.r1 > k) return design_.length1;
    return -kInf;
}

std::pair<double, double> TurnaroundPath::curvature_span(int piece) const {
    switch (piece) {
        case 1: return {1.0 / design_.r1, 1.0 / design_.r1};
        case 2: return {1.0 / design_.r2, 1.0 / design_.r2};
        // The spirals: from nearly straight far out to their curvature at A (and B).
        default: return {0.0, coil_in_.curvature_at(design_.entry_theta)};
    }
}

// Walks back piece by piece from `from`'s piece: the first piece holding a root holds the
// nearest one, and each piece's search returns its root nearest the search's start.
std::optional<Located> TurnaroundPath::behind(const Located& from, double chord) const {
    const int piece = from.place.piece;
    if (piece >= 3) {
        if (auto r = behind_on_coil_out(from, chord)) return r;
    }
    if (piece >= 2) {
        if (auto r = behind_on_arc(2, from, chord)) return r;
    }
    if (piece >= 1) {
        if (auto r = behind_on_arc(1, from, chord)) return r;
    }
    return behind_on_coil_in(from, chord);
}

// Circle-circle intersection in closed form. The chord circle (centre q, radius d) meets the
// arc's circle (centre c, radius r) at angles psi +- beta about c. Each root is measured as the
// backward angle from where the search starts on this arc (from's u if from is on it, else the
// arc's end); the smallest one within the arc's range is the nearest behind.
std::optional<Located> TurnaroundPath::behind_on_arc(int piece, const Located& from,
                                                     double chord) const {
    const bool first = piece == 1;
    const Vec2 c = first ? design_.c1 : design_.c2;
    const double r = first ? design_.r1 : design_.r2;
    const double u_begin = first ? u1_start_ : u2_start_;
    const double u_end = first ? u1_end_ : u2_end_;
    // Going back along the travel: u increases on arc 1 (clockwise), decreases on arc 2.
    const double back = first ? 1.0 : -1.0;
    const bool same = from.place.piece == piece;
    const double u0 = same ? from.place.u : u_end;
    const double room = back * (u_begin - u0);

    double psi, beta;
    if (same) {
        // from is on this circle: the chord subtends 2 asin(d / 2r) at the centre.
        if (chord > 2.0 * r) return std::nullopt;
        psi = u0;
        beta = 2.0 * math::asin(chord / (2.0 * r));
    } else {
        const Vec2 w = from.pos - c;
        const double dist = norm(w);
        if (dist > r + chord || dist < std::abs(r - chord) || dist == 0.0) return std::nullopt;
        // Foot of the common chord along w, and the half-width across it. r - x is formed as
        // (d - e)(d + e) / 2 dist with e = dist - r: the textbook (r^2 + dist^2 - d^2) / 2 dist
        // cancels when from sits on the arc's circle (at a join, with a link far shorter than
        // r), which left such chords wrong by 1e-9 relative (found by tests/fuzz/fuzz_chain).
        const double e = dist - r;
        const double r_minus_x = (chord - e) * (chord + e) / (2.0 * dist);
        const double x = r - r_minus_x;
        const double y2 = r_minus_x * (2.0 * r - r_minus_x);
        psi = math::atan2(w.y(), w.x());
        beta = math::atan2(std::sqrt(std::max(y2, 0.0)), x);
    }

    double best = kInf;
    for (const double root : {psi + beta, psi - beta}) {
        // Backward angle from u0, wrapped into [-slack, 2 pi - slack).
        double delta = std::fmod(back * (root - u0), kTwoPi);
        if (delta < -kJoinSlack) delta += kTwoPi;
        if (delta >= kTwoPi - kJoinSlack) delta -= kTwoPi;
        if (same && delta <= 0.0) continue;  // strictly behind from
        if (delta <= room + kJoinSlack && delta < best) best = delta;
    }
    if (best == kInf) return std::nullopt;
    return at({piece, u0 + back * best});
}

std::optional<Located> TurnaroundPath::behind_on_coil_in(const Located& from, double chord) const {
    if (from.place.piece == 0) return coil_in_.behind(from, chord);
    // From a later piece: march outward from A, which never steps over the first root. As on
    // the plain spiral (Spiral::behind), every root has b theta within the chord of |q|: the
    // march may start at (d - |q|) / b and stop a radian past (d + |q|) / b.
    const double b = coil_in_.b();
    const double r0 = norm(from.pos);
    const double start = std::max(design_.entry_theta, (chord - r0) / b);
    const auto u = march_to_chord(SpiralPiece{b}, SpiralBound{b}, from.pos, chord, start, +1.0,
                                  std::max(start, (chord + r0) / b + 1.0), kSpiralMarchStep);
    if (!u) return std::nullopt;
    return at({0, *u});
}

// On the coil-out spiral -P(theta), |-P(theta) - q| = |P(theta) + q|: the search runs down the
// coil-in spiral towards A with the mirrored point -q.
//
// From a place on the coil-out spiral itself (q' = P(theta)), with phi = theta - theta' the
// squared chord over b^2 is g(phi) = theta^2 + (theta - phi)^2 - 2 theta (theta - phi) cos(phi),
//   g'(phi) / 2 = phi - theta (1 - cos phi) + theta (theta - phi) sin phi
//              > 2 theta sin(phi/2) [(theta - phi) cos(phi/2) - sin(phi/2)],
// positive while theta - phi > tan(phi/2): on phi in (0, pi/2] whenever theta - phi >= 1. So when
// theta_A >= 1, g increases on (0, min(pi/2, theta - theta_A)], and if it reaches (chord/b)^2
// there the root is unique in that bracket: safeguarded Newton finds it. If g stays below on the
// whole piece there is no root on it. Otherwise (a chord reaching round more than a quarter
// turn) the curvature-bounded march decides.
std::optional<Located> TurnaroundPath::behind_on_coil_out(const Located& from, double chord) const {
    const double b = coil_in_.b();
    const double th = from.place.u, tha = design_.entry_theta;
    const double k2 = (chord / b) * (chord / b);
    // g summed without cancellation, as in Spiral::behind: phi^2 + 2 theta (theta - phi) (1 - cos phi).
    auto one_minus_cos = [](double c, double s) { return c > 0.0 ? s * s / (1.0 + c) : 1.0 - c; };
    auto g = [th, k2, one_minus_cos](double phi) {
        return phi * phi + 2.0 * th * (th - phi) * one_minus_cos(math::cos(phi), math::sin(phi)) - k2;
    };
    constexpr double kQuarter = 1.5707963267948966192313216916398;
    const double room = th - tha;
    const double hi0 = std::min(kQuarter, room);
    if (tha >= 1.0 && hi0 > 0.0) {
        const double g_hi = g(hi0);
        if (g_hi < 0.0 && room <= kQuarter) return std::nullopt;  // the whole piece is nearer
        if (g_hi >= 0.0) {
            double lo = 0.0, hi = hi0;
            // Start from the circle of radius ~theta: a chord k subtends 2 asin(k / 2 theta).
            const double k = std::sqrt(k2), rad = std::sqrt(th * th + 1.0);
            double phi = k < 2.0 * rad ? 2.0 * math::asin(k / (2.0 * rad)) : 0.5 * hi;
            if (!(phi > lo && phi < hi)) phi = 0.5 * (lo + hi);
            for (int it = 0; it < tol::max_newton; ++it) {
                const double t2 = th - phi, c = math::cos(phi), s = math::sin(phi);
                const double omc = one_minus_cos(c, s);
                const double gv = phi * phi + 2.0 * th * t2 * omc - k2;
                if (gv < 0.0) lo = phi; else hi = phi;
                const double dg = 2.0 * (phi - th * omc + th * t2 * s);
                double next = phi - gv / dg;
                if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
                const double step = next - phi;
                phi = next;
                // Relative to phi: far out on the spiral the root itself is tiny.
                if (std::abs(step) <= tol::newton_step * phi ||
                    hi - lo <= 4.0 * std::numeric_limits<double>::epsilon() * th)
                    break;
            }
            return at({3, th - phi});
        }
    }
    // No root within the monotone bracket (g < 0 all over it): the march may start at its end.
    const double start = (tha >= 1.0 && hi0 > 0.0) ? th - hi0 : th;
    const auto u = march_to_chord(SpiralPiece{b}, SpiralBound{b}, -from.pos, chord, start, -1.0, tha, kSpiralMarchStep);
    if (!u) return std::nullopt;
    return at({3, *u});
}

}  // namespace dragon
