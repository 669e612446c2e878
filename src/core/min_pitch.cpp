// Q3: the smallest pitch with which the head reaches the turning-space boundary collision-free.
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/make_path.hpp"
#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"

namespace dragon {

namespace {
constexpr double kTwoPi = 6.283185307179586476925286766559;
}

std::optional<Contact> contact_before_boundary(Scenario s, double pitch) {
    s.path.kind = PathKind::spiral;
    s.path.pitch = pitch;
    const Simulation sim(s);
    const auto& spiral = static_cast<const Spiral&>(sim.path());
    const double start_radius = spiral.b() * kTwoPi * s.path.start_turn;
    if (start_radius <= s.path.turn_radius)
        throw InputError(fmt::format("pitch {} puts the head's start (radius {:.4f} m) inside the turning "
                                     "space (radius {} m)", pitch, start_radius, s.path.turn_radius));
    // The moment the head front handle reaches radius turn_radius.
    const double theta_end = s.path.turn_radius / spiral.b();
    const double t_end = (-spiral.length_to(theta_end) - sim.start_arc()) / s.head_speed;
    return first_contact(sim, 0.0, t_end);
}

MinPitch min_pitch(const Scenario& s, double lo, double hi) {
    if (!(lo > s.bench.width) || !(hi > lo) || !std::isfinite(hi))
        throw InputError(fmt::format("pitch search range [{}, {}] is not allowed: it needs width {} < lo < hi",
                                     lo, hi, s.bench.width));
    MinPitch out{};
    out.search_lo = lo;
    out.search_hi = hi;
    // Scan from the top down on a grid, then bisect each change of feasibility.
    constexpr double kGrid = 2.5e-3;
    const int n = std::max(2, static_cast<int>(std::ceil((hi - lo) / kGrid)));
    auto feasible = [&](double p) { return !contact_before_boundary(s, p).has_value(); };
    std::vector<double> grid(static_cast<size_t>(n + 1));
    std::vector<bool> ok(grid.size());
    for (int k = 0; k <= n; ++k) {
        grid[static_cast<size_t>(k)] = lo + (hi - lo) * k / n;
        ok[static_cast<size_t>(k)] = feasible(grid[static_cast<size_t>(k)]);
    }
    std::vector<double> cuts;
    for (size_t k = 0; k + 1 < grid.size(); ++k) {
        if (ok[k] == ok[k + 1]) continue;
        double a = grid[k], b = grid[k + 1];
        const bool fa = ok[k];
        while (b - a > tol::pitch) {
            const double m = 0.5 * (a + b);
            if (m <= a || m >= b) break;
            if (feasible(m) == fa) a = m; else b = m;
        }
        cuts.push_back(fa ? a : b);  // keep the feasible side of the cut
    }
    double start = lo;
    bool state = ok.front();
    for (double c : cuts) {
        out.intervals.push_back({start, c, state});
        start = c;
        state = !state;
    }
    out.intervals.push_back({start, hi, state});
    out.pitch = std::numeric_limits<double>::quiet_NaN();
    // The smallest pitch p such that every pitch in [p, hi] is feasible, and the smallest feasible.
    for (const PitchInterval& iv : out.intervals)
        if (iv.feasible) { out.pitch = iv.lo; break; }
    out.guarantee = fmt::format(
        "feasibility evaluated on a {:.4g} m pitch grid over [{}, {}], each change bisected to {:.0e} m; "
        "each evaluation checks the whole run to the boundary with clearance-bounded time steps",
        (hi - lo) / n, lo, hi, tol::pitch);
    return out;
}

}  // namespace dragon
