#include "contours.hpp"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace dragon::render {

namespace {

// A grid edge a line can cross: the one from node (i, j) to (i + 1, j) or to (i, j + 1).
using EdgeId = std::uint64_t;

}  // namespace

std::vector<std::vector<Vec2>> contour_lines(const std::vector<double>& xs, const std::vector<double>& ys,
                                             const std::vector<double>& z, double level) {
    const std::size_t nx = xs.size(), ny = ys.size();
    if (nx < 2 || ny < 2 || z.size() != nx * ny) return {};
    const auto at = [&](std::size_t i, std::size_t j) { return z[i * ny + j]; };
    const auto horizontal = [&](std::size_t i, std::size_t j) -> EdgeId { return 2 * (i * ny + j); };
    const auto vertical = [&](std::size_t i, std::size_t j) -> EdgeId { return 2 * (i * ny + j) + 1; };
    std::unordered_map<EdgeId, Vec2> crossing;
    // Where the level crosses the edge from node p (value zp) to node q (value zq).
    const auto cross = [&](EdgeId e, const Vec2& p, double zp, const Vec2& q, double zq) {
        const double t = (level - zp) / (zq - zp);
        crossing.emplace(e, Vec2{p.x() + t * (q.x() - p.x()), p.y() + t * (q.y() - p.y())});
        return e;
    };
    std::vector<std::pair<EdgeId, EdgeId>> segments;
    for (std::size_t i = 0; i + 1 < nx; ++i) {
        for (std::size_t j = 0; j + 1 < ny; ++j) {
            // Corners anticlockwise from the bottom left: a (i, j), b (i+1, j), c (i+1, j+1), d (i, j+1).
            const double za = at(i, j), zb = at(i + 1, j), zc = at(i + 1, j + 1), zd = at(i, j + 1);
            if (std::isnan(za) || std::isnan(zb) || std::isnan(zc) || std::isnan(zd)) continue;
            const Vec2 a{xs[i], ys[j]}, b{xs[i + 1], ys[j]}, c{xs[i + 1], ys[j + 1]}, d{xs[i], ys[j + 1]};
            const int mask = (za >= level ? 1 : 0) | (zb >= level ? 2 : 0) | (zc >= level ? 4 : 0) | (zd >= level ? 8 : 0);
            if (mask == 0 || mask == 15) continue;
            const auto bottom = [&] { return cross(horizontal(i, j), a, za, b, zb); };
            const auto right = [&] { return cross(vertical(i + 1, j), b, zb, c, zc); };
            const auto top = [&] { return cross(horizontal(i, j + 1), d, zd, c, zc); };
            const auto left = [&] { return cross(vertical(i, j), a, za, d, zd); };
            const bool centre_above = 0.25 * (za + zb + zc + zd) >= level;
            switch (mask) {
                case 1: case 14: segments.emplace_back(left(), bottom()); break;
                case 2: case 13: segments.emplace_back(bottom(), right()); break;
                case 3: case 12: segments.emplace_back(left(), right()); break;
                case 4: case 11: segments.emplace_back(right(), top()); break;
                case 6: case 9: segments.emplace_back(bottom(), top()); break;
                case 7: case 8: segments.emplace_back(left(), top()); break;
                case 5:  // a and c above: joined through the centre, or apart
                    if (centre_above) segments.emplace_back(left(), top()), segments.emplace_back(bottom(), right());
                    else segments.emplace_back(left(), bottom()), segments.emplace_back(right(), top());
                    break;
                case 10:  // b and d above
                    if (centre_above) segments.emplace_back(left(), bottom()), segments.emplace_back(right(), top());
                    else segments.emplace_back(left(), top()), segments.emplace_back(bottom(), right());
                    break;
                default: break;
            }
        }
    }
    // Chain the segments through their shared edges: every edge joins at most two squares.
    std::unordered_map<EdgeId, std::vector<std::size_t>> at_edge;
    for (std::size_t k = 0; k < segments.size(); ++k) {
        at_edge[segments[k].first].push_back(k);
        at_edge[segments[k].second].push_back(k);
    }
    std::vector<bool> used(segments.size(), false);
    std::vector<std::vector<Vec2>> lines;
    const auto walk = [&](std::size_t first, EdgeId from) {
        std::vector<Vec2> line{crossing.at(from)};
        for (std::size_t k = first;;) {
            used[k] = true;
            const EdgeId to = segments[k].first == from ? segments[k].second : segments[k].first;
            line.push_back(crossing.at(to));
            std::size_t next = segments.size();
            for (std::size_t n : at_edge[to])
                if (!used[n]) next = n;
            if (next == segments.size()) break;
            from = to;
            k = next;
        }
        lines.push_back(std::move(line));
    };
    // Open lines from their ends first (an end is an edge on one segment only), then the loops.
    for (std::size_t k = 0; k < segments.size(); ++k) {
        if (used[k]) continue;
        if (at_edge[segments[k].first].size() == 1) walk(k, segments[k].first);
        else if (at_edge[segments[k].second].size() == 1) walk(k, segments[k].second);
    }
    for (std::size_t k = 0; k < segments.size(); ++k)
        if (!used[k]) walk(k, segments[k].first);
    return lines;
}

}  // namespace dragon::render
