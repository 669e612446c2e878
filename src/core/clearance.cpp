#include <algorithm>
#include <cmath>
#include <limits>

#include "core/sat.hpp"
#include "dragon/collision.hpp"

namespace dragon {

namespace {

double bounding_radius(const Rect& r) {
    return std::sqrt(r.half_length * r.half_length + r.half_width * r.half_width);
}

void consider(Clearance& best, const Frame& f, int i, int j) {
    const Rect& a = f.benches[static_cast<size_t>(i)];
    const Rect& b = f.benches[static_cast<size_t>(j)];
    // The projected gap is a lower bound on the distance: skip the exact test when it cannot win.
    if (sat_gap(a, b).gap >= best.distance) return;
    const Separation s = separation(a, b);
    if (s.distance < best.distance) best = {s.distance, i + 1, j + 1, s.axis, s.point};
}

}  // namespace

// Sweep and prune on bounding circles: sort the benches by the left edge of their bounding
// circle, then sweep; two rectangles within `margin` of each other have bounding circles within
// `margin` too, so no such pair is skipped. Adjacent benches (sharing a handle) are excluded.
std::vector<std::pair<int, int>> candidate_pairs(const Frame& f, double margin) {
    const size_t n = f.benches.size();
    // Sorted by the left edge of the widened circle; then the sweep reads plain arrays in order,
    // which is most of the broad phase's time.
    std::vector<std::pair<double, int>> order(n);
    for (size_t i = 0; i < n; ++i) {
        const Rect& r = f.benches[i];
        order[i] = {r.centre.x - bounding_radius(r), static_cast<int>(i)};
    }
    std::sort(order.begin(), order.end());
    std::vector<double> lo(n), hi(n), x(n), y(n), rad(n);
    std::vector<int> index(n);
    for (size_t k = 0; k < n; ++k) {
        const int i = order[k].second;
        const Rect& r = f.benches[static_cast<size_t>(i)];
        rad[k] = bounding_radius(r);
        x[k] = r.centre.x;
        y[k] = r.centre.y;
        lo[k] = x[k] - rad[k] - 0.5 * margin;
        hi[k] = x[k] + rad[k] + 0.5 * margin;
        index[k] = i;
    }
    std::vector<std::pair<int, int>> out;
    out.reserve(16 * n);
    for (size_t a = 0; a < n; ++a) {
        const double xa = x[a], ya = y[a], reach_a = rad[a] + margin, end = hi[a];
        const int ia = index[a];
        for (size_t b = a + 1; b < n && lo[b] <= end; ++b) {
            const double reach = reach_a + rad[b];
            const double dx = xa - x[b], dy = ya - y[b];
            if (dx * dx + dy * dy > reach * reach) continue;
            const int ib = index[b];
            if (ib - ia < 2 && ia - ib < 2) continue;  // neighbours share a handle
            out.emplace_back(std::min(ia, ib) + 1, std::max(ia, ib) + 1);
        }
    }
    return out;
}

Clearance clearance(const Frame& f, double cutoff) {
    Clearance best{std::numeric_limits<double>::infinity(), 0, 0, {}, {}};
    if (f.benches.size() < 3) return best;
    // Every pair closer than `margin` is a candidate, so a best candidate within the margin is
    // the true minimum; otherwise all pairs are farther apart than the margin.
    const double margin = std::min(cutoff, 1.0);
    const auto pairs = candidate_pairs(f, margin);
    // Exact distances only where the cheap projected gap (a lower bound) could still win:
    // seed with the pair of smallest gap, then test the rest against it.
    std::vector<double> gaps(pairs.size());
    size_t seed = 0;
    for (size_t k = 0; k < pairs.size(); ++k) {
        gaps[k] = sat_gap(f.benches[static_cast<size_t>(pairs[k].first - 1)],
                          f.benches[static_cast<size_t>(pairs[k].second - 1)]).gap;
        if (gaps[k] < gaps[seed]) seed = k;
    }
    if (!pairs.empty()) consider(best, f, pairs[seed].first - 1, pairs[seed].second - 1);
    for (size_t k = 0; k < pairs.size(); ++k)
        if (gaps[k] < best.distance) consider(best, f, pairs[k].first - 1, pairs[k].second - 1);
    if (best.distance <= margin) return best;
    if (cutoff <= margin) return {cutoff, best.bench_a, best.bench_b, best.axis, best.point};
    return clearance_all_pairs(f);
}

Clearance clearance_all_pairs(const Frame& f) {
    Clearance best{std::numeric_limits<double>::infinity(), 0, 0, {}, {}};
    const int n = static_cast<int>(f.benches.size());
    for (int i = 0; i < n; ++i)
        for (int j = i + 2; j < n; ++j) consider(best, f, i, j);
    return best;
}

}  // namespace dragon
