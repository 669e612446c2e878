#include "render/guide.hpp"

#include <algorithm>
#include <cmath>

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

std::vector<GuideRun> path_beziers(const Path& path, double s0, double s1, double max_step,
                                   double max_turn) {
    std::vector<GuideRun> runs;
    s0 = std::max(s0, path.s_min());
    s1 = std::min(s1, path.s_max());
    if (!(s1 > s0)) return runs;

    Located here = path.at_arc(s0);
    double s = s0;
    runs.push_back({here.place.piece, {here.pos}});
    while (s < s1) {
        const double kappa = std::abs(path.curvature(here.place));
        double h = std::min(max_step, kappa > 0 ? max_turn / kappa : max_step);
        h = std::max(h, 1e-6);
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
