#include "guide.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dragon::render {

namespace {

// Appends the cubic from a to b (a already in the list): a Hermite segment with unit-speed
// tangents, whose Bezier controls sit a third of the arc length along each tangent.
void append_segment(std::vector<Vec2>& out, const Located& a, const Located& b, double h) {
    out.push_back(a.pos + (h / 3.0) * a.tangent);
    out.push_back(b.pos - (h / 3.0) * b.tangent);
    out.push_back(b.pos);
}

// Arc position in (lo, hi] where the piece changes (lo's piece differs from hi's), by bisection.
double piece_boundary(const Path& path, double lo, double hi) {
    const int piece_lo = path.at_arc(lo).place.piece;
    for (int i = 0; i < 50 && hi - lo > 1e-9; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (path.at_arc(mid).place.piece == piece_lo) lo = mid;
        else hi = mid;
    }
    return hi;
}

}  // namespace

double signed_distance(const Box& box, const Vec2& p) {
    const double dx = std::max(box.lo.x() - p.x(), p.x() - box.hi.x()), dy = std::max(box.lo.y() - p.y(), p.y() - box.hi.y());
    if (dx <= 0 && dy <= 0) return std::max(dx, dy);  // inside: the nearer side
    return std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
}

std::vector<std::pair<double, double>> arcs_in_box(const Path& path, double s0, double s1, const Box& box,
                                                   double resolution) {
    std::vector<std::pair<double, double>> out;
    s0 = std::max(s0, path.s_min());
    s1 = std::min(s1, path.s_max());
    if (!(s1 > s0)) return out;
    // A step must move s: no finer than a few units in the last place of the arc positions.
    const double ulp = std::numeric_limits<double>::epsilon() * std::max(std::abs(s0), std::abs(s1));
    resolution = std::max(resolution, 8 * ulp);
    for (double s = s0; s < s1;) {
        const double d = signed_distance(box, path.at_arc(s).pos);
        const double next = std::min(s + std::max(std::abs(d), resolution), s1);
        if (d < resolution) {  // inside, or too close to tell: kept
            if (!out.empty() && out.back().second == s) out.back().second = next;
            else out.push_back({s, next});
        }
        s = next;
    }
    return out;
}

std::vector<std::pair<double, double>> split_by_piece(const Path& path, double s0, double s1) {
    std::vector<std::pair<double, double>> out;
    s0 = std::max(s0, path.s_min());
    s1 = std::min(s1, path.s_max());
    while (s1 > s0) {
        if (path.at_arc(s0).place.piece == path.at_arc(s1).place.piece) {
            out.push_back({s0, s1});
            break;
        }
        const double b = piece_boundary(path, s0, s1);
        out.push_back({s0, b});
        s0 = b;
    }
    return out;
}

std::vector<GuideRun> path_beziers(const Path& path, double s0, double s1, double max_step,
                                   double max_turn, double min_step) {
    std::vector<GuideRun> runs;
    s0 = std::max(s0, path.s_min());
    s1 = std::min(s1, path.s_max());
    if (!(s1 > s0)) return runs;

    // A step must move s: no shorter than a few units in the last place of the arc positions.
    min_step = std::max(min_step, 8 * std::numeric_limits<double>::epsilon() * std::max(std::abs(s0), std::abs(s1)));
    max_step = std::max(max_step, min_step);
    Located here = path.at_arc(s0);
    double s = s0;
    runs.push_back({here.place.piece, {here.pos}});
    while (s < s1) {
        const double kappa = std::abs(path.curvature(here.place));
        double h = std::min(max_step, kappa > 0 ? max_turn / kappa : max_step);
        h = std::max(h, min_step);
        double s_next = std::min(s + h, s1);
        Located next = path.at_arc(s_next);
        if (next.place.piece != here.place.piece) {
            // End this run exactly at the piece boundary; the next run starts there.
            s_next = piece_boundary(path, s, s_next);
            next = path.at_arc(s_next);
            append_segment(runs.back().beziers, here, next, s_next - s);
            runs.push_back({next.place.piece, {next.pos}});
        } else {
            append_segment(runs.back().beziers, here, next, s_next - s);
        }
        here = next;
        s = s_next;
    }
    std::erase_if(runs, [](const GuideRun& r) { return r.beziers.size() < 4; });
    return runs;
}

}  // namespace dragon::render
