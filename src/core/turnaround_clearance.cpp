// How close the benches come on the turnaround run, up to their first contact.
//
// The first contact over the window is found exactly (first_contact_travel, as `collide` finds
// it). Up to it (over the whole window when there is none) the smallest clearance is found by a
// scan in head travel on the motion at 1 m/s, so that it is the same at any head speed.
//
// The scan samples the clearance every kScanTravel of head travel and refines each local minimum
// of the samples that could hold the least by golden section. It decides nothing about
// contact: whether the benches touch is the exact search's answer, whose steps no contact can
// fit between. (A proof that no dip between samples goes lower, from the clearance's largest
// rate of change, was tried: near flat minima a first-order bound needs thousands of samples,
// 15,000 for the contest's run, to come within 1 cm.) With `prove` the least found is then
// enclosed: the window is walked again, each step proved to keep every pair farther apart than
// kClearanceProofGap under it (contact::prove_step's apart_by: enclosures over the whole step).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "golden_section.hpp"
#include "swept_proof.hpp"
#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"
#include "dragon/turnaround.hpp"

namespace dragon {

namespace {

// Scan step as head travel, m (0.05 s at the contest's 1 m/s): where the benches are depends
// only on how far the head has come.
constexpr double kScanTravel = 0.05;
// The scan's cost cap, in bench rectangles checked (samples times benches): ~20 s on one core.
// The contest's run takes 9e5.
constexpr double kMaxBenchChecks = 1e8;
// Pairs farther apart than this count as this far, m: only the smallest clearance matters, and
// the broad phase then looks at nearby pairs only.
constexpr double kCutoff = 0.5;
// Golden-section stop on a local minimum's place, m of head travel.
constexpr double kPlaceTolerance = 1e-9;

struct Sample {
    double x;  // head travel, m
    double c;  // clearance, m (capped at kCutoff)
};

class Probe {
public:
    explicit Probe(const Simulation& unit) : unit_(unit) {}
    Clearance at(double x) {
        ++evaluations;
        unit_.frame_at_travel_into(x, f_);
        return clearance(f_, kCutoff);
    }
    Sample sample(double x) { return {x, at(x).distance}; }
    int evaluations = 0;

private:
    const Simulation& unit_;
    Frame f_;
};


// m: how far under the smallest clearance found the proof's lower bound is set (with `prove`),
// so that the least clearance is enclosed to this. The steps must enclose each bench to within
// it where the closest pair passes, so the cost grows as it shrinks: on the contest's run with
// first-order enclosures alone 964 steps at 1e-3 m, 1212 at 1e-4, 1916 at 1e-5, 4198 at 1e-6
// (1 s), with the second order too 783 at 1e-6; the printed 6 decimals need 1e-6.
constexpr double kClearanceProofGap = 1e-6;
// m of head travel: the first step the proof tries, and the shortest it takes before giving up.
constexpr double kFirstProofStep = 1.0;
constexpr double kLeastProofStep = 1e-9;

// Proves that no two non-adjacent benches come within `lower` of each other anywhere over
// [from, to] (m of head travel on `unit`), step by step as the first contact's steps are proved
// (contact::prove_step): a step not proved is halved, one proved lets the next grow.
ClearanceProof prove_clearance(const Simulation& unit, double from, double to, double lower, const InlineExecutor& stop) {
    ClearanceProof out;
    out.lower = lower;
    contact::SweptWorkspace ws;
    Frame f0, f1;
    unit.frame_at_travel_into(from, f0);
    double x = from, h = kFirstProofStep;
    contact::Enclosures order = contact::Enclosures::either;  // the order that proved the last step first
    while (x < to) {
        check_stop(stop);
        const double y = std::min(to, x + h);
        unit.frame_at_travel_into(y, f1);
        const contact::StepProof p =
            contact::prove_step(unit.path(), unit.scenario().bench, f0, f1, ws, lower, order);
        if (p.verdict != contact::StepVerdict::proved) {
            ++out.subdivisions;
            h = 0.5 * (y - x);
            if (h < kLeastProofStep) return out;
            continue;
        }
        ++out.steps;
        order = contact::tried_first_after(p);
        x = y;
        std::swap(f0, f1);
        h *= 1.5;
    }
    out.proved = true;
    return out;
}

}  // namespace

RunClearance min_clearance(const Scenario& scenario, const RunWindow& window, const WorkProgress& progress,
                           Executor* executor, bool prove) {
    Scenario s = scenario;
    s.path.kind = PathKind::turnaround;
    const Simulation sim(s);
    const Simulation unit = sim.at_speed(1.0);
    const double v = s.head_speed;
    const WindowCut cut = cut_window(sim, window);
    RunClearance out{};
    out.window = cut.searched(v);
    out.jam = cut.after ? cut.after : cut.before;
    const double samples = std::ceil((cut.to - cut.from) / kScanTravel);
    if (!(samples * s.bench.bench_count <= kMaxBenchChecks))
        throw InputError(Key::clearance_range, fmt::format("{}..{} m of head travel", cut.from, cut.to),
                         fmt::format("the clearance scan would check {:.3g} chains of {} benches (at most {:.0e} "
                                     "bench checks); narrow it, or leave the clearance out", samples,
                                     s.bench.bench_count, kMaxBenchChecks));

    // The first contact, exactly, over the whole window: the clearance is looked at up to it.
    ContactSearchOptions options;
    options.executor = executor;
    options.prove_steps = prove;
    options.proof = &out.proof;
    out.first_contact = first_contact_travel(sim, cut.from, cut.to, options);
    out.scan_travel = kScanTravel;
    out.scan_step = kScanTravel / v;
    if (const std::optional<Contact>& c = out.first_contact) {
        // Up to the contact the least clearance is the contact itself.
        out.distance = 0.0;
        out.time = c->time;
        out.travel = c->travel;
        out.bench_a = c->bench_a;
        out.bench_b = c->bench_b;
        if (progress) progress(1, 1);
        return out;
    }

    Probe probe(unit);
    const int steps = std::max(2, static_cast<int>(samples));
    const double dx = (cut.to - cut.from) / steps;
    std::vector<Sample> scan(static_cast<size_t>(steps) + 1);
    const InlineExecutor stop(executor);
    for (int k = 0; k <= steps; ++k) {
        if (k % 128 == 0) check_stop(stop);
        scan[static_cast<size_t>(k)] = probe.sample(k == steps ? cut.to : cut.from + k * dx);  // the end exactly: it may be a jam's
        if (progress) progress(k + 1, steps + 1);
    }

    // Each local minimum of the samples refined by golden section: the best found so far.
    out.distance = std::numeric_limits<double>::infinity();
    auto consider = [&](double x, const Clearance& c) {
        if (c.distance < out.distance && c.distance < kCutoff && c.bench_a > 0) {
            out.distance = c.distance;
            out.travel = x;
            out.bench_a = c.bench_a;
            out.bench_b = c.bench_b;
        }
    };
    const auto nearer = [](const Clearance& x, const Clearance& y) { return x.distance < y.distance; };
    const double best_sample = std::min_element(scan.begin(), scan.end(), [](const Sample& a, const Sample& b) {
                                   return a.c < b.c;
                               })->c;
    for (int k = 0; k <= steps; ++k) {
        const size_t i = static_cast<size_t>(k);
        const double left = k == 0 ? scan[i].c : scan[i - 1].c, right = k == steps ? scan[i].c : scan[i + 1].c;
        // A plateau counts once, at its first sample.
        if ((k > 0 && scan[i].c >= left) || scan[i].c > right || scan[i].c >= kCutoff) continue;
        // Within a step of it the clearance falls at most about as fast as towards its neighbours.
        if (scan[i].c - 2.0 * std::max(left - scan[i].c, right - scan[i].c) > best_sample) continue;
        const double a = scan[static_cast<size_t>(std::max(0, k - 1))].x, b = scan[static_cast<size_t>(std::min(steps, k + 1))].x;
        const auto [at, best] = golden_min([&](double x) { return probe.at(x); }, a, b, kPlaceTolerance, nearer);
        consider(at, best);
    }
    if (!(out.distance <= best_sample)) {
        // No pair within the cutoff anywhere (or a minimum at an end of the window): the samples' least.
        for (const Sample& p : scan)
            if (p.c <= best_sample) consider(p.x, probe.at(p.x));  // (one sample, or a few tied)
    }

    if (out.bench_a == 0) out.distance = kCutoff;
    out.time = out.travel / v;
    out.evaluations = probe.evaluations;
    if (prove) out.clearance_proof = prove_clearance(unit, cut.from, cut.to, out.distance - kClearanceProofGap, stop);
    return out;
}

}  // namespace dragon
