#include "untouched_tail.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "dragon/constants.hpp"
#include "dragon/path.hpp"

namespace dragon {

namespace {

// Every bound is widened by this much (relative) and every angle comparison by this much of the
// angle: far above the rounding of the doubles they come from, far below anything that matters.
constexpr double kSlack = 1e-9;
// A bench whose reach spans more whole turns than this is so near the centre that proving
// anything is not worth it: the whole chain is watched.
constexpr int kMaxTurnsApart = 8;

}  // namespace

std::optional<BenchReach> bench_reach(double b, const BenchSpec& spec, int bench, double front_last, double rear_last,
                                      double span_first) {
    const double d = spec.link_length(bench);
    const double o = spec.hole_offset;
    const double hw = 0.5 * spec.width;
    const double rho = b * front_last;        // the nearer handle's least radius
    const double corner = std::hypot(o, hw);  // the farthest a board point is from the link
    if (!(rho > 0.5 * d)) return std::nullopt;
    // The link's points are at least `seg` from the centre (both handles are at least rho out);
    // the chord's line over the board's length at least `line`, any point of the board `near`.
    const double seg = std::sqrt(rho * rho - 0.25 * d * d);
    if (!(seg > 2.0 * corner)) return std::nullopt;
    const double line = seg - o;
    const double near = seg - corner;
    // Along the chord's line f(s) = rho - b psi has |f''| <= 1/|x| + b/|x|^2, and is zero at the
    // two handles; across the board |grad f| = sqrt(1 + (b/rho)^2).
    const double curv = 1.0 / line + b / (line * line);
    const double grad = std::sqrt(1.0 + (b / near) * (b / near));
    // f'' > 0 when the line passes farther than 2b from the centre: f is then convex, below zero
    // between the holes and above it beyond them, and each side has its own, smaller bound. The
    // line's distance is rho_a rho_b sin(angle) / d, least at the last frame's radii and the
    // first frame's angle.
    const double h = rho * (b * rear_last) * std::sin(span_first) / d;
    double in = curv * d * d / 8.0, out = curv * o * (d + o) / 2.0;
    if (!(h > 2.0 * b)) in = out = std::max(in, out);
    const double widen = 1.0 + kSlack;
    return BenchReach{(in + grad * hw) * widen, (out + grad * hw) * widen, std::asin(corner / seg) * widen};
}

namespace {

// The stretch is one the certificate covers: both frames on the spiral with every handle's theta
// not rising, every link at the last frame under a quarter turn with theta_k > tan(angle / 2),
// and no link's angle shrinking.
bool coils_in_steadily(const std::vector<double>& first, const std::vector<double>& last) {
    for (size_t k = 0; k < first.size(); ++k) {
        if (!(first[k] >= last[k])) return false;
        if (k + 1 == first.size()) break;
        const double span_last = last[k + 1] - last[k], span_first = first[k + 1] - first[k];
        if (!(span_last > 0.0 && span_last < 0.5 * std::numbers::pi && last[k] > std::tan(0.5 * span_last))) return false;
        if (!(span_first > 0.0 && span_first <= span_last * (1.0 + kSlack))) return false;
    }
    return true;
}

std::vector<double> thetas(const Frame& f) {
    std::vector<double> out(f.handles.size());
    for (size_t k = 0; k < out.size(); ++k) out[k] = f.handles[k].place.u;
    return out;
}

}  // namespace

int benches_that_may_touch(const Spiral& spiral, const BenchSpec& spec, const Frame& first, const Frame& last) {
    const int n = spec.bench_count;
    const size_t handles = static_cast<size_t>(n) + 1;
    if (first.handles.size() != handles || last.handles.size() != handles || !(first.time <= last.time)) return n;
    for (const Frame* f : {&first, &last})
        for (const Handle& h : f->handles)
            if (h.place.piece != 0) return n;
    const std::vector<double> tf = thetas(first), tl = thetas(last);
    if (!coils_in_steadily(tf, tl)) return n;

    const double b = spiral.b(), pitch = spiral.pitch();
    std::vector<BenchReach> reach(handles);  // reach[i] of bench i = 1..n
    for (int i = 1; i <= n; ++i) {
        const size_t k = static_cast<size_t>(i);
        const std::optional<BenchReach> r = bench_reach(b, spec, i, tl[k - 1], tl[k], tf[k] - tf[k - 1]);
        if (!r) return n;
        reach[k] = *r;
    }
    // The largest inward reach and angle of any bench from i on, to find each bench's candidate
    // partners by bisection before checking them one by one.
    std::vector<double> in_from(handles + 1, 0.0), angle_from(handles + 1, 0.0);
    for (size_t k = handles - 1; k >= 1; --k) {
        in_from[k] = std::max(in_from[k + 1], reach[k].in);
        angle_from[k] = std::max(angle_from[k + 1], reach[k].angle);
    }

    int watched = std::min(n, 2);
    // Outermost first, so that most benches find their partners all at or below the answer so far.
    for (int i = n - 2; i >= 1; --i) {
        const size_t ki = static_cast<size_t>(i);
        const BenchReach& ri = reach[ki];
        const size_t j0 = ki + 2;
        // Unwrapped angles 2 pi m apart put the offsets p m apart: m below 0 never fits (the
        // angle spans could not overlap), m above top is too many pitches for the offsets.
        const double turns = (ri.out + in_from[j0]) / pitch;
        if (turns > kMaxTurnsApart) return n;
        for (int m = 0; m <= static_cast<int>(turns); ++m) {
            const double shift = kTwoPi * m;
            // The widest the two spans' margins can be, with the comparisons' slack (which is
            // largest for the outermost handle).
            const double widest = ri.angle + angle_from[j0] + kSlack * (1.0 + tl.back());
            // Candidates: theta_{j-1} - theta_i <= shift + widest at the first frame, and
            // theta_j - theta_{i-1} >= shift - widest at the last frame.
            const double top_theta = tf[ki] + shift + widest;
            const size_t top = static_cast<size_t>(std::upper_bound(tf.begin(), tf.end(), top_theta) - tf.begin());
            // theta_{j-1} <= top_theta for j - 1 < top, so j <= top.
            const size_t j_hi = std::min(top, static_cast<size_t>(n));
            const double low_theta = tl[ki - 1] + shift - widest;
            const size_t j_lo = std::max(j0, static_cast<size_t>(std::lower_bound(tl.begin(), tl.end(), low_theta) - tl.begin()));
            for (size_t j = j_hi; j >= j_lo && static_cast<int>(j) > watched; --j) {
                const BenchReach& rj = reach[j];
                const double apart = ri.angle + rj.angle;
                const double slack = kSlack * (1.0 + tl[j]);
                const bool offsets_meet = pitch * m <= ri.out + rj.in;
                const bool behind = tf[j - 1] - tf[ki] > shift + apart + slack;       // j's span beyond i's
                const bool ahead = tl[j] - tl[ki - 1] < shift - apart - slack;       // j's span short of i's
                if (offsets_meet && !behind && !ahead) {
                    watched = static_cast<int>(j);
                    break;
                }
            }
        }
    }
    return watched;
}

}  // namespace dragon
