// Randomised differential tests: the library's searches against independent ones written here,
// on many short-chain scenarios a run (seeded; a failure prints the scenario).
//
// The independent searches share only the model with the library (the chain solver and the
// rectangles' separation): a dense scan of the whole run in head travel, with every local
// minimum of the clearance among the samples refined by golden section (so that a contact
// window narrower than the spacing, as near a critical pitch, is not lost between two
// samples), then bisection. They are slow and simple; the library's are fast and bounded.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <sstream>
#include <vector>

#include "support/random_bench.hpp"
#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"
#include "dragon/turnaround.hpp"

using namespace dragon;

namespace {

constexpr unsigned kSeed = 20261124;

std::string describe(const Scenario& s) {
    std::ostringstream o;
    o.precision(17);
    o << "--path " << to_string(s.path.kind) << " --bench-count " << s.bench.bench_count << " --head-length "
      << s.bench.head_length << " --body-length " << s.bench.body_length << " --width " << s.bench.width
      << " --hole-offset " << s.bench.hole_offset << " --speed " << s.head_speed << " --pitch " << s.path.pitch
      << " --start-turn " << s.path.start_turn << " --turn-radius " << s.path.turn_radius << " --turn-pitch "
      << s.path.turn_pitch << " --arc-ratio " << s.path.arc_ratio;
    return o.str();
}

// A random short dragon: a dozen or two benches of any reasonable make, on a spiral a few turns
// long or on a turnaround of any pitch and ratio, at one of three head speeds.
Scenario random_scenario(std::mt19937& rng, PathKind kind) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (;;) {
        Scenario s;
        s.path.kind = kind;
        dragon_test::draw_bench(s.bench, rng);
        const double speeds[] = {0.05, 1.0, 5.0};
        s.head_speed = speeds[static_cast<int>(u(rng) * 3) % 3];
        s.path.pitch = s.bench.width + 0.05 + 0.6 * u(rng);
        s.path.start_turn = 3.0 + 4.0 * u(rng);
        s.path.turn_radius = 2.5 + 2.0 * u(rng);
        s.path.turn_pitch = 0.8 + 1.2 * u(rng);
        s.path.arc_ratio = 0.75 + 1.5 * u(rng);
        try {
            validate(s);
            const Simulation sim(s);
            (void)sim.valid_range();
            return s;
        } catch (const InputError&) {
        }
    }
}

// Independent first contact over head travel [x0, x1] (on the motion at 1 m/s): the clearance
// of every pair sampled every `spacing`, each local minimum of the samples refined, then
// bisection on the first sign change to 1e-12 m.
std::optional<double> scanned_contact(const Simulation& unit, double x0, double x1, double spacing) {
    const auto clear = [&](double x) { return clearance_all_pairs(unit.frame(x)).distance; };
    const int n = std::max(2, static_cast<int>(std::ceil((x1 - x0) / spacing)));
    std::vector<double> x(static_cast<size_t>(n) + 1), c(x.size());
    for (int k = 0; k <= n; ++k) {
        x[static_cast<size_t>(k)] = k == n ? x1 : x0 + (x1 - x0) * k / n;
        c[static_cast<size_t>(k)] = clear(x[static_cast<size_t>(k)]);
    }
    if (c[0] <= 0.0) return x0;
    for (size_t k = 1; k < x.size(); ++k) {
        double lo = x[k - 1], hi = x[k];
        if (c[k] > 0.0) {
            // A dip between samples: golden section for the least clearance on [x_{k-1}, x_{k+1}]
            // around a local minimum of the samples, then a contact if it goes through zero.
            if (k + 1 >= x.size() || !(c[k] <= c[k - 1] && c[k] <= c[k + 1])) continue;
            double a = x[k - 1], b = x[k + 1];
            const double g = 0.5 * (std::sqrt(5.0) - 1.0);
            double p = b - g * (b - a), q = a + g * (b - a), fp = clear(p), fq = clear(q);
            while (b - a > 1e-12 && fp > 0.0 && fq > 0.0) {
                if (fp <= fq) b = q, q = p, fq = fp, p = b - g * (b - a), fp = clear(p);
                else a = p, p = q, fp = fq, q = a + g * (b - a), fq = clear(q);
            }
            if (fp > 0.0 && fq > 0.0) continue;
            lo = x[k - 1];
            hi = fp <= 0.0 ? p : q;
            // The dip's first crossing lies between the sample before and the first point found below zero.
        }
        while (hi - lo > 1e-12) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            (clear(mid) > 0.0 ? lo : hi) = mid;
        }
        return hi;
    }
    return std::nullopt;
}

}  // namespace

// The library's first contact against the scan, on the plain spiral from t = 0 to where the
// dragon can follow it and on the turnaround's window.
TEST(RandomDifferential, FirstContactOnBothPaths) {
    std::mt19937 rng(kSeed);
    int contacts = 0;
    for (int round = 0; round < 24; ++round) {
        const PathKind kind = round % 2 ? PathKind::turnaround : PathKind::spiral;
        const Scenario s = random_scenario(rng, kind);
        const Simulation sim(s);
        const Simulation unit = sim.at_speed(1.0);
        // (Benches overlapping where the window starts have no first contact in it: collide
        // refuses, and the search reports the start.)
        const CollideAnswer lib = first_contact_covering(sim, 0.0, 0.0);
        const std::optional<double> scan = scanned_contact(unit, lib.window.from_travel, lib.window.to_travel, 0.02);
        ASSERT_EQ(lib.contact.has_value(), scan.has_value()) << describe(s);
        if (!scan) continue;
        ++contacts;
        // The same event: the travel within the two searches' tolerances, the time as travel / speed.
        EXPECT_NEAR(lib.contact->travel, *scan, 2e-10) << describe(s);
        EXPECT_NEAR(lib.contact->time * s.head_speed, lib.contact->travel, 1e-12 * (1.0 + std::abs(lib.contact->travel)))
            << describe(s);
        // And real: overlapping (or touching) at it, apart just before it, by every pair (unless
        // they overlap already where the window starts).
        EXPECT_LE(clearance_all_pairs(unit.frame(lib.contact->travel)).distance, 1e-12) << describe(s);
        if (!lib.overlapping) {
            EXPECT_GT(clearance_all_pairs(unit.frame(lib.contact->travel - 1e-9)).distance, 0.0) << describe(s);
        }
    }
    EXPECT_GE(contacts, 6);  // the draw holds contacts, not only collision-free runs
}

// The smallest pitch, against a scan of pitches whose runs are checked by the independent scan
// and whose last change is narrowed by bisection.
TEST(RandomDifferential, MinimumPitch) {
    std::mt19937 rng(kSeed + 1);
    int changes = 0;
    for (int round = 0; round < 8; ++round) {
        Scenario s = random_scenario(rng, PathKind::spiral);
        s.bench.bench_count = 8 + round;  // short: every pitch is a whole scan
        const double lo = s.bench.width + 0.02, hi = lo + 0.3;
        // The head starts at radius pitch * start turn: outside the turning space at every pitch.
        s.path.turn_radius = 0.6 * lo * s.path.start_turn;
        const auto feasible = [&](double p) {
            Scenario q = s;
            q.path.pitch = p;
            q.head_speed = 1.0;
            const Simulation run(q);
            const double end = boundary_travel(run);
            const std::optional<Jam> jam = run.jam_before_travel(end);
            if (jam) return false;
            return !scanned_contact(run, 0.0, end, 0.02).has_value();
        };
        // The same grid as the scan below (the library's is (hi - lo) / 60 too): both see the same
        // states at the same pitches, and narrow the same change.
        MinPitchOptions options;
        options.grid = 0.005;
        const MinPitch m = min_pitch(s, lo, hi, options);
        // The independent answer: the first feasible pitch on a finer grid, then bisection.
        const int n = 60;
        std::optional<double> first;
        double below = lo;
        for (int k = 0; k <= n; ++k) {
            const double p = lo + (hi - lo) * k / n;
            if (feasible(p)) {
                first = p;
                break;
            }
            below = p;
        }
        if (!first) {
            EXPECT_TRUE(m.above_range) << describe(s);
            continue;
        }
        if (*first == lo) {
            EXPECT_TRUE(m.below_range) << describe(s);
            continue;
        }
        double a = below, b = *first;
        while (b - a > 1e-9) {
            const double mid = 0.5 * (a + b);
            (feasible(mid) ? b : a) = mid;
        }
        ASSERT_FALSE(std::isnan(m.pitch)) << describe(s);
        // Each is known to 1e-9 m.
        EXPECT_NEAR(m.pitch, b, 3e-9) << describe(s);
        ++changes;
    }
    EXPECT_GE(changes, 2);  // the draw holds changes inside the range, not only all-or-nothing ones
}

// The largest head speed, against the speed ratio sampled densely over the window and each
// local maximum refined.
TEST(RandomDifferential, LargestHeadSpeed) {
    std::mt19937 rng(kSeed + 2);
    int bounded = 0;
    for (int round = 0; round < 10; ++round) {
        const Scenario s = random_scenario(rng, PathKind::turnaround);
        const MaxSpeed m = max_head_speed(s, 2.0);
        if (m.unbounded) continue;
        ++bounded;
        const Simulation sim(s);
        const double s0 = sim.start_arc() + m.window.from_travel, s1 = sim.start_arc() + m.window.to_travel;
        const auto ratio = [&](double arc) { return speed_ratio_at(sim.path(), s.bench, arc).ratio; };
        const int n = static_cast<int>((s1 - s0) / 0.004);
        std::vector<double> r(static_cast<size_t>(n) + 1);
        for (int k = 0; k <= n; ++k) r[static_cast<size_t>(k)] = ratio(s0 + (s1 - s0) * k / n);
        const double best_sample = *std::max_element(r.begin(), r.end());
        double best = best_sample;
        for (int k = 1; k < n; ++k) {
            const size_t i = static_cast<size_t>(k);
            // Local maxima of the samples near the top (between samples 4 mm apart the ratio
            // rises by far less than 0.05), each refined by golden section.
            if (!(r[i] >= r[i - 1] && r[i] >= r[i + 1]) || r[i] < best_sample - 0.05) continue;
            double a = s0 + (s1 - s0) * (k - 1) / n, b = s0 + (s1 - s0) * (k + 1) / n;
            const double g = 0.5 * (std::sqrt(5.0) - 1.0);
            double p = b - g * (b - a), q = a + g * (b - a), fp = ratio(p), fq = ratio(q);
            while (b - a > 1e-10) {
                if (fp >= fq) b = q, q = p, fq = fp, p = b - g * (b - a), fp = ratio(p);
                else a = p, p = q, fp = fq, q = a + g * (b - a), fq = ratio(q);
            }
            best = std::max({best, fp, fq});
        }
        // The library's maximum is at least every sample and refined peak, and no more than the
        // ratio somewhere in the window (it is a value the chain reaches).
        EXPECT_GE(m.ratio, best * (1.0 - 1e-9)) << describe(s);
        EXPECT_NEAR(m.ratio, ratio(sim.start_arc() + m.travel), 1e-12 * m.ratio) << describe(s);
        EXPECT_NEAR(m.max_head_speed, 2.0 / best, 1e-8) << describe(s);
    }
    EXPECT_GE(bounded, 5);
}
