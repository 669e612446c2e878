#include <algorithm>
#include <cmath>
#include <limits>

#include "sat.hpp"
#include "dragon/collision.hpp"

namespace dragon {

namespace {

void consider(Clearance& best, const Frame& f, int i, int j) {
    const Rect& a = f.benches[static_cast<size_t>(i)];
    const Rect& b = f.benches[static_cast<size_t>(j)];
    // The projected gap is a lower bound on the distance: skip the exact test when it cannot win.
    if (projected_gap(a, b) >= best.distance) return;
    const Separation s = separation(a, b);
    if (s.distance < best.distance) best = {s.distance, i + 1, j + 1, s.axis, s.point};
}

}  // namespace

// Sweep and prune: sort the benches by the left edge of their bounding box, then sweep along x.
// Two rectangles within `margin` of each other have x-extents within `margin` and bounding
// circles within `margin`, so no such pair is skipped; the box's x-extent is the sweep band
// (narrower than the circle's for a bench lying across x), the circles are the filter.
// Adjacent benches (sharing a handle) are excluded.
const std::vector<std::pair<int, int>>& BroadPhase::candidate_pairs(const Frame& f, double margin) {
    const size_t n = f.benches.size();
    // Sorted by the left edge of the box; then the sweep reads plain arrays in order, which is
    // most of the broad phase's time.
    auto half_x = [](const Rect& r) { return r.half_length * std::abs(r.axis.x()) + r.half_width * std::abs(r.axis.y()); };
    // The order of the last call is kept: successive frames of a search differ little, so it is
    // nearly sorted already and insertion sort finishes it in about n steps.
    std::vector<std::pair<double, int>>& order = order_;
    std::vector<double> &lo = lo_, &hi = hi_, &x = x_, &y = y_, &rad = rad_;
    std::vector<int>& index = index_;
    if (order.size() != n) {
        order.resize(n);
        for (size_t i = 0; i < n; ++i) order[i].second = static_cast<int>(i);
    }
    for (auto& [key, i] : order) key = f.benches[static_cast<size_t>(i)].centre.x() - half_x(f.benches[static_cast<size_t>(i)]);
    for (size_t k = 1; k < n; ++k) {
        const auto item = order[k];
        size_t j = k;
        for (; j > 0 && item < order[j - 1]; --j) order[j] = order[j - 1];
        order[j] = item;
    }
    for (auto* v : {&lo, &hi, &x, &y, &rad}) v->resize(n);
    index.resize(n);
    for (size_t k = 0; k < n; ++k) {
        const int i = order[k].second;
        const Rect& r = f.benches[static_cast<size_t>(i)];
        rad[k] = half_diagonal(r);
        x[k] = r.centre.x();
        y[k] = r.centre.y();
        lo[k] = x[k] - half_x(r) - 0.5 * margin;
        hi[k] = x[k] + half_x(r) + 0.5 * margin;
        index[k] = i;
    }
    // Branch-free inner loop: every pair in the sweep band is written, and the write position
    // advances only for the ones that pass (which pass is unpredictable, so a branch there
    // mispredicts often; this is most of the clearance pass's time otherwise).
    std::vector<std::pair<int, int>>& out = pairs_;
    if (out.size() < 64) out.resize(64);
    size_t count = 0;
    for (size_t a = 0; a < n; ++a) {
        const double xa = x[a], ya = y[a], reach_a = rad[a] + margin, end = hi[a];
        const int ia = index[a];
        size_t stop = a + 1;
        while (stop < n && lo[stop] <= end) ++stop;
        if (out.size() < count + (stop - a)) out.resize(2 * (count + (stop - a)));
        for (size_t b = a + 1; b < stop; ++b) {
            const double reach = reach_a + rad[b];
            const double dx = xa - x[b], dy = ya - y[b];
            const int ib = index[b];
            const bool near = dx * dx + dy * dy <= reach * reach;
            const bool apart = ib - ia >= 2 || ia - ib >= 2;  // neighbours share a handle
            out[count] = {std::min(ia, ib) + 1, std::max(ia, ib) + 1};
            count += static_cast<size_t>(near & apart);
        }
    }
    out.resize(count);
    return out;
}

std::vector<std::pair<int, int>> candidate_pairs(const Frame& f, double margin) {
    BroadPhase scratch;
    return scratch.candidate_pairs(f, margin);
}

Clearance clearance(const Frame& f, double cutoff) {
    BroadPhase scratch;
    return clearance(f, cutoff, scratch);
}

Clearance clearance(const Frame& f, double cutoff, BroadPhase& scratch) {
    Clearance best{std::numeric_limits<double>::infinity(), 0, 0, Vec2::Zero(), Vec2::Zero()};
    if (f.benches.size() < 3) return best;
    // Every pair closer than `margin` is a candidate, so a best candidate within the margin is
    // the true minimum; otherwise all pairs are farther apart than the margin.
    const double margin = std::min(cutoff, 1.0);
    const auto& pairs = scratch.candidate_pairs(f, margin);
    // Exact distances only where the cheap projected gap (a lower bound) could still win:
    // seed with the pair of smallest gap, then test the rest against it.
    std::vector<double>& gaps = scratch.gaps_;
    gaps.resize(pairs.size());
    size_t seed = 0;
    for (size_t k = 0; k < pairs.size(); ++k) {
        gaps[k] = projected_gap(f.benches[static_cast<size_t>(pairs[k].first - 1)],
                                f.benches[static_cast<size_t>(pairs[k].second - 1)]);
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
    Clearance best{std::numeric_limits<double>::infinity(), 0, 0, Vec2::Zero(), Vec2::Zero()};
    const int n = static_cast<int>(f.benches.size());
    for (int i = 0; i < n; ++i)
        for (int j = i + 2; j < n; ++j) consider(best, f, i, j);
    return best;
}

std::vector<Overlap> overlaps(const Frame& f) {
    std::vector<Overlap> out;
    for (const auto& [a, b] : candidate_pairs(f, 0.0)) {
        const Separation s = separation(f.benches[static_cast<size_t>(a - 1)], f.benches[static_cast<size_t>(b - 1)]);
        if (s.distance < 0.0) out.push_back({a, b, -s.distance, s.point});
    }
    std::sort(out.begin(), out.end(), [](const Overlap& x, const Overlap& y) { return x.depth > y.depth; });
    return out;
}

}  // namespace dragon
