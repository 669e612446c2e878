// The proved first-contact search (ContactSearchOptions::prove_steps) against a brute-force scan
// on one scenario and window: shared by the seeded test (tests/core/test_contact_vs_scan.cpp)
// and the libFuzzer target (tests/fuzz/fuzz_contact.cpp).
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
#pragma once

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "support/random_bench.hpp"
#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"

namespace dragon_test {

inline constexpr double kCoarse = 0.02;  // m of head travel between the scan's samples
inline constexpr double kFine = 1e-4;    // m of head travel between its samples across a dip

struct ContactCase {
    dragon::Scenario scenario;
    double from = 0.0, to = 0.0;  // m of head travel
    // The case as the tool's flags, to run it again.
    std::string describe() const {
        std::ostringstream o;
        o.precision(17);
        const dragon::Scenario& s = scenario;
        o << "dragon collide --prove --path " << to_string(s.path.kind) << " --bench-count " << s.bench.bench_count
          << " --head-length " << s.bench.head_length << " --body-length " << s.bench.body_length << " --width "
          << s.bench.width << " --hole-offset " << s.bench.hole_offset << " --speed " << s.head_speed;
        if (s.path.kind == dragon::PathKind::spiral)
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
// the window: the checks are the scan's. None when `tries` draws give no such case.
template <class Uniform>
std::optional<ContactCase> draw_contact_case(Uniform& u, dragon::PathKind kind, bool contact, int tries) {
    using namespace dragon;
    for (int t = 0; t < tries; ++t) {
        ContactCase c;
        Scenario& s = c.scenario;
        s.path.kind = kind;
        draw_bench_with(s.bench, u);
        s.head_speed = 0.5 + 2.0 * u();
        s.path.pitch = s.bench.width + 0.05 + 0.5 * u();
        s.path.start_turn = 5.0 + 6.0 * u();
        s.path.turn_radius = 2.5 + 2.0 * u();
        s.path.turn_pitch = 0.5 + 1.5 * u();
        s.path.arc_ratio = 0.75 + 1.5 * u();
        try {
            validate(s);
            const Simulation sim(s);
            const CollideAnswer motion = first_contact_of_motion(sim);
            const double lo = motion.window.from_travel, hi = motion.window.to_travel;
            if (contact) {
                if (!motion.contact || motion.overlapping || motion.contact->travel < lo + 1.0) continue;
                const double x = motion.contact->travel;
                c.from = std::max(lo, x - 2.0 - 18.0 * u());
                c.to = std::min(hi, x + 0.05 + 2.0 * u());
            } else {
                if (motion.overlapping) continue;
                const double end = motion.contact ? motion.contact->travel - 0.05 : hi;
                c.to = end - (end - lo) * 0.5 * u();
                c.from = std::max(lo, c.to - 5.0 - 20.0 * u());
                if (c.to - c.from < 1.0) continue;
            }
            return c;
        } catch (const InputError&) {
        }
    }
    return std::nullopt;
}

// The scan's samples: head travel and the clearance there, in order of travel.
struct ScanSample {
    double travel;    // m
    double distance;  // m: clearance_all_pairs, <= 0 where benches touch
};

inline std::vector<ScanSample> scan_clearance(const dragon::Simulation& unit, double x0, double x1) {
    const auto clear = [&](double x) { return ScanSample{x, dragon::clearance_all_pairs(unit.frame(x)).distance}; };
    const int n = std::max(2, static_cast<int>(std::ceil((x1 - x0) / kCoarse)));
    std::vector<ScanSample> coarse;
    for (int k = 0; k <= n; ++k) coarse.push_back(clear(k == n ? x1 : x0 + (x1 - x0) * k / n));
    std::vector<ScanSample> all = coarse;
    // Past the first coarse sample touching, fine samples tell nothing the checks read.
    for (size_t k = 0; k < coarse.size(); ++k) {
        const double c = coarse[k].distance;
        const bool dip = (k == 0 || c <= coarse[k - 1].distance) && (k + 1 == coarse.size() || c <= coarse[k + 1].distance);
        if (!dip && c > 0.0) continue;
        const double a = coarse[k == 0 ? 0 : k - 1].travel, b = coarse[std::min(k + 1, coarse.size() - 1)].travel;
        for (double x = a + kFine; x < b; x += kFine) all.push_back(clear(x));
        if (c <= 0.0) break;
    }
    std::sort(all.begin(), all.end(), [](const ScanSample& p, const ScanSample& q) { return p.travel < q.travel; });
    return all;
}

// What the proved search found over the case's window, and every way it contradicts the scan
// (empty when it agrees).
struct ContactVsScan {
    bool found = false;  // a contact in the window
    std::vector<std::string> violations;
};

inline ContactVsScan compare_with_scan(const ContactCase& c) {
    using namespace dragon;
    ContactVsScan out;
    const auto fail = [&](const std::string& what) { out.violations.push_back(what); };
    const auto num = [](double v) {
        std::ostringstream o;
        o.precision(17);
        o << v;
        return o.str();
    };
    const Simulation sim(c.scenario);
    const Simulation unit = sim.at_speed(1.0);  // its time is head travel
    ContactProof proof;
    ContactSearchOptions options;
    options.prove_steps = true;
    options.proof = &proof;
    const std::optional<Contact> found = first_contact_travel(sim, c.from, c.to, options);
    const std::vector<ScanSample> samples = scan_clearance(unit, c.from, c.to);

    // The first touching sample, and the last clear one before it.
    const auto first_touch =
        std::find_if(samples.begin(), samples.end(), [](const ScanSample& p) { return p.distance <= 0.0; });
    // Every sample over the travel the accepted steps cover is apart (with no step accepted,
    // benches touching where the window starts, they cover nothing). A step where a link turned
    // too far for the enclosures rests on its rate bound (proof.unproved_steps; on a spiral a few
    // turns wide under a long head bench, every step may): the scan checks it all the same.
    if (proof.proved_from != c.from) fail("the proof starts at " + num(proof.proved_from) + " m, not the window's start");
    const bool stepped = proof.proved_steps + proof.unproved_steps > 0;
    for (const ScanSample& p : samples)
        if (stepped && p.travel >= proof.proved_from && p.travel <= proof.proved_to && !(p.distance > 0.0))
            fail("a touching sample at " + num(p.travel) + " m, inside the travel the steps cover, [" +
                 num(proof.proved_from) + ", " + num(proof.proved_to) + "] m");

    if (!found) {
        if (first_touch != samples.end()) fail("no contact found, but benches touch at " + num(first_touch->travel) + " m");
        if (proof.proved_to != c.to) fail("no contact found, but the steps end at " + num(proof.proved_to) + " m");
        return out;
    }
    out.found = true;
    const Contact& hit = *found;
    if (hit.enclosure_lo != proof.proved_to) fail("the enclosure starts at " + num(hit.enclosure_lo) + " m, not where the steps end");
    if (hit.enclosure_hi != hit.travel) fail("the enclosure ends at " + num(hit.enclosure_hi) + " m, not at the contact");
    if (!(hit.enclosure_lo <= hit.enclosure_hi)) fail("the enclosure is empty");
    if (first_touch == samples.end() || hit.travel < first_touch->travel - kFine - hit.travel_tolerance) {
        // An earlier contact than any the scan saw: between its samples, and real.
        if (!(clearance_all_pairs(unit.frame(hit.travel)).distance <= 0.0))
            fail("the contact at " + num(hit.travel) + " m, before any the scan saw, is not one");
        return out;
    }
    // No later than the first touching sample (so than any), and the scan's crossing, between
    // the clear sample before it and it, within the enclosure.
    if (hit.travel > first_touch->travel + hit.travel_tolerance)
        fail("the contact at " + num(hit.travel) + " m is later than the scan's first, at " + num(first_touch->travel) + " m");
    if (first_touch->travel < hit.enclosure_lo)
        fail("the scan touches at " + num(first_touch->travel) + " m, before the enclosure's start " + num(hit.enclosure_lo) + " m");
    if (first_touch != samples.begin()) {
        if (std::prev(first_touch)->travel > hit.enclosure_hi)
            fail("the scan is clear at " + num(std::prev(first_touch)->travel) + " m, after the enclosure's end " +
                 num(hit.enclosure_hi) + " m");
    } else if (hit.travel != c.from) {
        fail("benches touch where the window starts, but the contact is at " + num(hit.travel) + " m");
    }
    return out;
}

}  // namespace dragon_test
