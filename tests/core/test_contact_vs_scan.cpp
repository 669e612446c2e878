// The proved first-contact search (ContactSearchOptions::prove_steps) against a brute-force scan,
// on random scenarios and random windows of their motion (seeded: the same cases every run; a
// failure prints the case as the tool's flags).
//
// The scan shares only the model with the search (the chain solver and clearance_all_pairs,
// every non-adjacent pair's separation, with no broad phase, bounds or steps): the clearance
// every kCoarse m of head travel, then every kFine m across each dip of it (each local minimum
// of the coarse samples, and each coarse sample touching), where a contact narrower than the
// coarse spacing would hide. What the search claims, it must not contradict:
//  - its first contact is no later than any sample where benches touch (to its own tolerance),
//    and within the fine spacing of the scan's first touching sample unless it is an earlier
//    contact the scan stepped over, which must then be real (the benches touch there);
//  - with no contact found, no sample touches;
//  - every sample in the travel its steps cover (proof.proved_from .. proved_to) is apart, so the
//    enclosure [enclosure_lo, enclosure_hi] holds the scan's crossing: its first touching sample
//    is at or after enclosure_lo, the clear sample before that at or before enclosure_hi.
// The libFuzzer targets of tests/fuzz run only under scripts/fuzz.sh (clang); this comparison
// draws its cases from a fixed seed instead, so that ctest runs it in every build (under a
// second in Release).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/random_bench.hpp"
#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"

using namespace dragon;

namespace {

constexpr unsigned kSeed = 20261127;
constexpr double kCoarse = 0.02;  // m of head travel between the scan's samples
constexpr double kFine = 1e-4;    // m of head travel between its samples across a dip

struct Case {
    Scenario scenario;
    double from = 0.0, to = 0.0;  // m of head travel
    std::string describe() const {
        std::ostringstream o;
        o.precision(17);
        const Scenario& s = scenario;
        o << "dragon collide --prove --path " << to_string(s.path.kind) << " --bench-count " << s.bench.bench_count
          << " --head-length " << s.bench.head_length << " --body-length " << s.bench.body_length << " --width "
          << s.bench.width << " --hole-offset " << s.bench.hole_offset << " --speed " << s.head_speed;
        if (s.path.kind == PathKind::spiral)
            o << " --pitch " << s.path.pitch << " --start-turn " << s.path.start_turn;
        else
            o << " --turn-radius " << s.path.turn_radius << " --turn-pitch " << s.path.turn_pitch << " --arc-ratio "
              << s.path.arc_ratio;
        o << " --from " << from << "m --to " << to << "m";
        return o.str();
    }
};

// A random short dragon of any reasonable make, on the spiral or the turnaround, and a window of
// its motion: with `contact`, 2 to 20 m of head travel before the motion's first contact to just
// past it (the scenario drawn again until it has one, not where its default window starts); else
// 5 to 25 m ending before it (or anywhere, with none). The motion's first contact only places
// the window: the checks are the scan's.
Case random_case(std::mt19937& rng, PathKind kind, bool contact) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (;;) {
        Case c;
        Scenario& s = c.scenario;
        s.path.kind = kind;
        dragon_test::draw_bench(s.bench, rng);
        s.head_speed = 0.5 + 2.0 * u(rng);
        s.path.pitch = s.bench.width + 0.05 + 0.5 * u(rng);
        s.path.start_turn = 5.0 + 6.0 * u(rng);
        s.path.turn_radius = 2.5 + 2.0 * u(rng);
        s.path.turn_pitch = 0.5 + 1.5 * u(rng);
        s.path.arc_ratio = 0.75 + 1.5 * u(rng);
        try {
            validate(s);
            const Simulation sim(s);
            const CollideAnswer motion = first_contact_of_motion(sim);
            const double lo = motion.window.from_travel, hi = motion.window.to_travel;
            if (contact) {
                if (!motion.contact || motion.overlapping || motion.contact->travel < lo + 1.0) continue;
                const double x = motion.contact->travel;
                c.from = std::max(lo, x - 2.0 - 18.0 * u(rng));
                c.to = std::min(hi, x + 0.05 + 2.0 * u(rng));
            } else {
                if (motion.overlapping) continue;
                const double end = motion.contact ? motion.contact->travel - 0.05 : hi;
                c.to = end - (end - lo) * 0.5 * u(rng);
                c.from = std::max(lo, c.to - 5.0 - 20.0 * u(rng));
                if (c.to - c.from < 1.0) continue;
            }
            return c;
        } catch (const InputError&) {
        }
    }
}

// The scan's samples: head travel and the clearance there, in order of travel.
struct Sample {
    double travel;    // m
    double distance;  // m: clearance_all_pairs, <= 0 where benches touch
};

std::vector<Sample> scan(const Simulation& unit, double x0, double x1) {
    const auto clear = [&](double x) { return Sample{x, clearance_all_pairs(unit.frame(x)).distance}; };
    const int n = std::max(2, static_cast<int>(std::ceil((x1 - x0) / kCoarse)));
    std::vector<Sample> coarse;
    for (int k = 0; k <= n; ++k) coarse.push_back(clear(k == n ? x1 : x0 + (x1 - x0) * k / n));
    std::vector<Sample> all = coarse;
    // Past the first coarse sample touching, fine samples tell nothing the checks read.
    for (size_t k = 0; k < coarse.size(); ++k) {
        const double c = coarse[k].distance;
        const bool dip = (k == 0 || c <= coarse[k - 1].distance) && (k + 1 == coarse.size() || c <= coarse[k + 1].distance);
        if (!dip && c > 0.0) continue;
        const double a = coarse[k == 0 ? 0 : k - 1].travel, b = coarse[std::min(k + 1, coarse.size() - 1)].travel;
        for (double x = a + kFine; x < b; x += kFine) all.push_back(clear(x));
        if (c <= 0.0) break;
    }
    std::sort(all.begin(), all.end(), [](const Sample& p, const Sample& q) { return p.travel < q.travel; });
    return all;
}

}  // namespace

TEST(ContactVsScan, ProvedFirstContactAgreesWithABruteForceScan) {
    std::mt19937 rng(kSeed);
    int contacts = 0, clear_windows = 0;
    for (int round = 0; round < 16; ++round) {
        const Case c = random_case(rng, round % 2 ? PathKind::turnaround : PathKind::spiral, round % 4 < 2);
        SCOPED_TRACE(c.describe());
        const Simulation sim(c.scenario);
        const Simulation unit = sim.at_speed(1.0);  // its time is head travel
        ContactProof proof;
        ContactSearchOptions options;
        options.prove_steps = true;
        options.proof = &proof;
        const std::optional<Contact> found = first_contact_travel(sim, c.from, c.to, options);
        const std::vector<Sample> samples = scan(unit, c.from, c.to);

        // The first touching sample, and the last clear one before it.
        const auto first_touch = std::find_if(samples.begin(), samples.end(), [](const Sample& p) { return p.distance <= 0.0; });
        // Every sample over the travel the accepted steps cover is apart (with no step accepted,
        // benches touching where the window starts, they cover nothing). A step where a link
        // turned too far for the enclosures rests on its rate bound (proof.unproved_steps; on a
        // spiral a few turns wide under a long head bench, every step may): the scan checks it
        // all the same.
        EXPECT_EQ(proof.proved_from, c.from);
        const bool stepped = proof.proved_steps + proof.unproved_steps > 0;
        for (const Sample& p : samples) {
            if (stepped && p.travel >= proof.proved_from && p.travel <= proof.proved_to) {
                EXPECT_GT(p.distance, 0.0) << "a touching sample at " << p.travel << " m, inside the travel the steps cover, ["
                                           << proof.proved_from << ", " << proof.proved_to << "] m";
            }
        }

        if (!found) {
            ++clear_windows;
            EXPECT_TRUE(first_touch == samples.end()) << "no contact found, but benches touch at " << first_touch->travel << " m";
            EXPECT_EQ(proof.proved_to, c.to);
            continue;
        }
        ++contacts;
        const Contact& hit = *found;
        EXPECT_EQ(hit.enclosure_lo, proof.proved_to);
        EXPECT_EQ(hit.enclosure_hi, hit.travel);
        EXPECT_LE(hit.enclosure_lo, hit.enclosure_hi);
        if (first_touch == samples.end() || hit.travel < first_touch->travel - kFine - hit.travel_tolerance) {
            // An earlier contact than any the scan saw: between its samples, and real.
            EXPECT_LE(clearance_all_pairs(unit.frame(hit.travel)).distance, 0.0) << "the contact at " << hit.travel << " m";
            continue;
        }
        // No later than the first touching sample (so than any), and the scan's crossing,
        // between the clear sample before it and it, within the enclosure.
        EXPECT_LE(hit.travel, first_touch->travel + hit.travel_tolerance);
        EXPECT_GE(first_touch->travel, hit.enclosure_lo);
        if (first_touch != samples.begin()) {
            EXPECT_LE(std::prev(first_touch)->travel, hit.enclosure_hi);
        } else {
            EXPECT_EQ(hit.travel, c.from);  // touching where the window starts
        }
    }
    // The draw holds both kinds of window.
    EXPECT_GE(contacts, 6);
    EXPECT_GE(clear_windows, 6);
}
