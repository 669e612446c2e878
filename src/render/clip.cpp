#include "clip.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace dragon::render {

namespace {

constexpr double pi = std::numbers::pi;
// More points than any arc in a picture of 16384 px needs (about a thousand); a bound on the
// work whatever the input.
constexpr int max_arc_points = 1 << 16;

std::array<Vec2, 4> corners_of(const Box& b) { return {b.lo, Vec2{b.hi.x(), b.lo.y()}, b.hi, Vec2{b.lo.x(), b.hi.y()}}; }

double distance_to_box(const Box& b, const Vec2& p) {
    return std::hypot(std::max({b.lo.x() - p.x(), 0.0, p.x() - b.hi.x()}), std::max({b.lo.y() - p.y(), 0.0, p.y() - b.hi.y()}));
}

double farthest_corner(const Box& b, const Vec2& p) {
    double d = 0;
    for (Vec2 q : corners_of(b)) d = std::max(d, distance(p, q));
    return d;
}

// The angles of the circle about c that can cross the box: all of them when c is in the box,
// else the box's angular span seen from c (under pi: the box is convex and c outside it).
std::pair<double, double> angles_over(const Vec2& c, const Box& box) {
    if (box.holds(c)) return {0.0, 2 * pi};
    const Vec2 mid = 0.5 * (box.lo + box.hi);
    const double base = std::atan2(mid.y() - c.y(), mid.x() - c.x());
    double lo = pi, hi = -pi;
    for (Vec2 q : corners_of(box)) {
        double a = std::atan2(q.y() - c.y(), q.x() - c.x()) - base;
        a = std::remainder(a, 2 * pi);
        lo = std::min(lo, a);
        hi = std::max(hi, a);
    }
    return {base + lo, base + hi};
}

// Points on the circle over [a0, a1], each chord within `tolerance` of the arc: a chord
// spanning angle h strays r (1 - cos(h / 2)) ~ r h^2 / 8 from it.
std::vector<Vec2> arc_points(const Vec2& c, double r, double a0, double a1, double tolerance) {
    const double step = std::min(pi / 8, std::sqrt(8 * tolerance / r));
    const int n = std::clamp(static_cast<int>(std::ceil((a1 - a0) / step)), 1, max_arc_points);
    std::vector<Vec2> pts;
    pts.reserve(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) {
        const double a = a0 + (a1 - a0) * i / n;
        pts.push_back(c + r * Vec2{std::cos(a), std::sin(a)});
    }
    return pts;
}

}  // namespace

std::vector<Vec2> clip_polygon(std::vector<Vec2> polygon, const Box& box) {
    // Each side as a linear function, >= 0 inside.
    const std::array<std::pair<Vec2, double>, 4> sides{{{{1, 0}, -box.lo.x()},
                                                        {{-1, 0}, box.hi.x()},
                                                        {{0, 1}, -box.lo.y()},
                                                        {{0, -1}, box.hi.y()}}};
    for (const auto& [n, k] : sides) {
        if (polygon.empty()) break;
        std::vector<Vec2> out;
        Vec2 prev = polygon.back();
        double fp = dot(n, prev) + k;
        for (Vec2 cur : polygon) {
            const double fc = dot(n, cur) + k;
            if ((fc >= 0) != (fp >= 0)) out.push_back(prev + (fp / (fp - fc)) * (cur - prev));
            if (fc >= 0) out.push_back(cur);
            prev = cur;
            fp = fc;
        }
        polygon = std::move(out);
    }
    return polygon;
}

std::vector<std::vector<Vec2>> clip_polyline(const std::vector<Vec2>& line, bool closed, const Box& box) {
    std::vector<std::vector<Vec2>> pieces;
    const std::size_t n = line.size();
    const std::size_t segments = n < 2 ? 0 : closed ? n : n - 1;
    bool joined = false;  // the last piece ends at the previous segment's own end
    for (std::size_t i = 0; i < segments; ++i) {
        const Vec2 p = line[i], q = line[(i + 1) % n], d = q - p;
        double t0 = 0, t1 = 1;
        bool keep = true;
        const std::array<std::pair<double, double>, 4> limits{
            {{-d.x(), p.x() - box.lo.x()}, {d.x(), box.hi.x() - p.x()}, {-d.y(), p.y() - box.lo.y()}, {d.y(), box.hi.y() - p.y()}}};
        for (auto [pk, qk] : limits) {
            if (pk == 0) {
                keep = keep && qk >= 0;
            } else if (pk < 0) {
                t0 = std::max(t0, qk / pk);
            } else {
                t1 = std::min(t1, qk / pk);
            }
        }
        if (!keep || t0 > t1) {
            joined = false;
            continue;
        }
        const Vec2 a = t0 == 0 ? p : p + t0 * d, b = t1 == 1 ? q : p + t1 * d;
        if (joined && t0 == 0) pieces.back().push_back(b);
        else pieces.push_back({a, b});
        joined = t1 == 1;
    }
    return pieces;
}

std::vector<Vec2> disk_in_box(const Vec2& c, double r, const Box& box, double tolerance) {
    if (!(r > distance_to_box(box, c))) return {};
    if (r >= farthest_corner(box, c)) {
        const auto k = corners_of(box);
        return {k.begin(), k.end()};
    }
    const auto [a0, a1] = angles_over(c, box);
    std::vector<Vec2> pts = arc_points(c, r, a0, a1, tolerance);
    // From outside, the sector over those angles holds all of the disk the box does.
    if (!box.holds(c)) pts.push_back(c);
    return clip_polygon(std::move(pts), box);
}

std::vector<std::vector<Vec2>> circle_in_box(const Vec2& c, double r, const Box& box, double tolerance) {
    if (!(r > distance_to_box(box, c)) || r >= farthest_corner(box, c)) return {};
    const auto [a0, a1] = angles_over(c, box);
    return clip_polyline(arc_points(c, r, a0, a1, tolerance), false, box);
}

}  // namespace dragon::render
