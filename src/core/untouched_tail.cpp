#include "untouched_tail.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "dragon/constants.hpp"
#include "dragon/path.hpp"
#include "dragon/portable_math.hpp"

namespace dragon {

namespace {

// Every bound is widened by this much (relative) and every angle comparison by this much of the
// angle: far above the rounding of the doubles they come from, far below anything that matters.
constexpr double kSlack = 1e-9;
// A bench whose reach spans more whole turns than this is so near the centre that proving
// anything is not worth it: the whole chain is watched.
constexpr int kMaxTurnsApart = 8;

}  // namespace

namespace {

// A lower bound on the double math::sin(x) returns, for 0 < x < 1.6: sin x >= x - x^3 / 6 there,
// and the slack covers this sum's rounding and math::sin's (under an ulp each), so that a product
// with it is never larger than the same product with math::sin(x) (rounding is monotone).
double sin_below(double x) { return (x - x * x * x / 6.0) * (1.0 - 1e-12); }

// bench_reach with hypot(hole offset, half width), the same for every bench, given.
std::optional<BenchReach> reach_of(double b, const BenchSpec& spec, int bench, double front_last, double rear_last,
                                   double span_first, double corner) {
    const double d = spec.link_length(bench);
    const double o = spec.hole_offset;
    const double hw = 0.5 * spec.width;
    const double rho = b * front_last;  // the nearer handle's least radius
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
    // first frame's angle. Almost everywhere the lower bound on the sine settles the comparison
    // as the sine itself would (sin_below): the sine is taken only where it does not.
    const double scale = rho * (b * rear_last);
    const bool small_angle = span_first > 0.0 && span_first < 1.6;
    const bool far_line = (small_angle && scale * sin_below(span_first) / d > 2.0 * b) ||
                          scale * math::sin(span_first) / d > 2.0 * b;
    double in = curv * d * d / 8.0, out = curv * o * (d + o) / 2.0;
    if (!far_line) in = out = std::max(in, out);
    const double widen = 1.0 + kSlack;
    return BenchReach{(in + grad * hw) * widen, (out + grad * hw) * widen, math::asin(corner / seg) * widen};
}

}  // namespace

std::optional<BenchReach> bench_reach(double b, const BenchSpec& spec, int bench, double front_last, double rear_last,
                                      double span_first) {
    return reach_of(b, spec, bench, front_last, rear_last, span_first, math::hypot(spec.hole_offset, 0.5 * spec.width));
}

namespace {

// The stretch is one the certificate covers: both frames on the spiral with every handle's theta
// not rising, every link at the last frame under a quarter turn with theta_k > tan(angle / 2),
// and no link's angle shrinking. Under a quarter turn the half angle's tangent is at most 1 (a
// rounding of a value below 1), so a theta above 1 passes without it.
bool coils_in_steadily(const std::vector<double>& first, const std::vector<double>& last) {
    for (size_t k = 0; k < first.size(); ++k) {
        if (!(first[k] >= last[k])) return false;
        if (k + 1 == first.size()) break;
        const double span_last = last[k + 1] - last[k], span_first = first[k + 1] - first[k];
        if (!(span_last > 0.0 && span_last < 0.5 * std::numbers::pi && (last[k] > 1.0 || last[k] > math::tan(0.5 * span_last))))
            return false;
        if (!(span_first > 0.0 && span_first <= span_last * (1.0 + kSlack))) return false;
    }
    return true;
}

// The first index in sorted `v` whose value is above `x` (std::upper_bound), for an answer
// expected at or just after `from` (every value before `from` is at most x): a few steps out from
// there, then a bisection over what is left.
size_t upper_bound_from(const std::vector<double>& v, size_t from, double x) {
    size_t k = from;
    for (size_t probes = 0; k < v.size() && probes < 4; ++k, ++probes)
        if (v[k] > x) return k;
    return static_cast<size_t>(std::upper_bound(v.begin() + static_cast<std::ptrdiff_t>(k), v.end(), x) - v.begin());
}

}  // namespace

ChainAngles chain_angles(const Frame& f) {
    ChainAngles out;
    out.time = f.time;
    out.theta.resize(f.handles.size());
    for (size_t k = 0; k < f.handles.size(); ++k) {
        out.theta[k] = f.handles[k].place.u;
        if (f.handles[k].place.piece != 0) out.on_spiral = false;
    }
    return out;
}

int benches_that_may_touch(const Spiral& spiral, const BenchSpec& spec, const Frame& first, const Frame& last) {
    return benches_that_may_touch(spiral, spec, chain_angles(first), chain_angles(last));
}

int benches_that_may_touch(const Spiral& spiral, const BenchSpec& spec, const ChainAngles& first,
                           const ChainAngles& last) {
    const int n = spec.bench_count;
    const size_t handles = static_cast<size_t>(n) + 1;
    if (first.theta.size() != handles || last.theta.size() != handles || !(first.time <= last.time)) return n;
    if (!first.on_spiral || !last.on_spiral) return n;
    const std::vector<double>&tf = first.theta, &tl = last.theta;
    if (!coils_in_steadily(tf, tl)) return n;

    const double b = spiral.b(), pitch = spiral.pitch();
    const double corner = math::hypot(spec.hole_offset, 0.5 * spec.width);
    std::vector<BenchReach> reach(handles);  // reach[i] of bench i = 1..n
    for (int i = 1; i <= n; ++i) {
        const size_t k = static_cast<size_t>(i);
        const std::optional<BenchReach> r = reach_of(b, spec, i, tl[k - 1], tl[k], tf[k] - tf[k - 1], corner);
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
            // Every theta up to tf[ki] is at most top_theta (shift and widest are not negative).
            const size_t top = upper_bound_from(tf, ki + 1, top_theta);
            // theta_{j-1} <= top_theta for j - 1 < top, so j <= top.
            const size_t j_hi = std::min(top, static_cast<size_t>(n));
            if (j_hi < j0 || static_cast<int>(j_hi) <= watched) continue;  // no candidate: the loop below is empty
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
