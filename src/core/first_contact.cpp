// Q2: the first moment two non-adjacent benches touch.
//
// The search runs in head travel (m from the head's place at t = 0), on the motion at 1 m/s:
// the chain's shape depends on the travel alone, so the contact found is the same, bit for bit,
// at any head speed, and its time is travel / speed.
//
// Stepping: at head travel x every pair of benches has separation g_ij > 0 and, from the
// benches' exact rigid-body velocity fields, a bound L_ij on how fast g_ij can shrink per metre
// of travel now. The step
//     h = min_ij g_ij / (rate_safety L_ij)    (m of head travel)
// skips no contact as long as the true closing speed stays below rate_safety times the bound
// over the step: an assumption, checked at the step's end (a broken bound sends the search back
// with a shorter step), not a proof. With ContactSearchOptions::prove_steps each step is then
// proved contact-free from the chain at its two ends (swept_proof.hpp), and one that is not is
// taken again shorter: the rate bounds choose, the enclosures prove (and where the benches stay
// far apart a step may reach past the rates' one, standing on its proof alone). Pairs within the broad
// phase's margin get their own rate bounds (and second-order ones near grazing passes, checked at
// the next evaluation); pairs beyond it are bounded group by group (far_pairs_step); benches or
// groups on different turns may instead take a bound from their radii about the centre, which
// neighbouring turns sliding past each other do not shrink (radial_step). The test
// Q2.EveryStepDeclaredSafeIsSafe samples inside every step, on runs with a window of contact
// that opens and closes. Near the contact a Newton probe on the closest pair brackets the root,
// which is then refined by bisection to tol::travel.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

#include "chain_front.hpp"
#include "contact_step.hpp"
#include "untouched_tail.hpp"
#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"
#include "dragon/executor.hpp"

namespace dragon {

namespace {

using contact::Approach;
using contact::kMargin;
using contact::kMaxTravel;
using contact::kProbeGap;
using contact::Overlap;
using contact::overlap_of;
using contact::PairMemory;
using contact::StepRecord;
using contact::Workspace;

// Head travel one proof of the untouched tail covers (untouched_tail.hpp): a shorter stretch
// proves more of the tail untouched (the chain's reach is judged at its innermost moment), for
// two more frames and a restart of the stepping. Measured on Q3's runs: 10 m watches about
// 8 of the contest's 223 benches on average, against 30 for one proof of the whole run.
constexpr double kStretchTravel = 10.0;  // m
// The proof of the last steps before a contact stops where the step it fails to prove is below
// this fraction (dimensionless) of the travel left to the contact (or below tol::travel): there
// the pair's gap is within the proof's slack (contact::kProofSlack) of zero.
constexpr double kFinalStep = 1e-3;
// The share of the travel left before the contact's bracket that the proof of the last steps
// tries next after a proved step (dimensionless). Doubling each proved step, as before, reached
// for the whole of what was left, failed, and halved: two tries for each halving of the travel
// to go (about 70 near the contest's contact). 15/16 leaves a sixteenth at each proved step
// when the gap at the step's end decides; nearer 1 a try fails more often (Q2's proof:
// 0.5: 34.9e6 instructions, 0.9: 33.1e6, 15/16: 32.8e6, 0.99: 33.2e6, 0.999: 35.5e6).
constexpr double kFinalReach = 15.0 / 16.0;
// m of head travel: a step neither the handles' motion nor their speed bounds can enclose
// (not_monotone) is taken again shorter down to this, then accepted on its rate bound: the
// speed bounds tighten as the step shrinks (on the turnaround's tight arcs, at 3:1, steps of a
// few centimetres are enclosed where the search's were not), but a link that turns by more
// than the bounds allow at any length would halve for ever.
constexpr double kLeastEnclosedStep = 1e-4;
// How much the cap a failed proof set grows with each step proved at it (dimensionless). Where
// the enclosures prove less than the rates' step (Q2's last 10 m) the cap holds the steps just
// below what they prove: 1.5 failed every other step there; 1.1 takes as many steps with half
// the failures (a sixth fewer instructions in the proved search at pitches 0.44 to 0.55 m).
constexpr double kProofCapGrowth = 1.1;
// Steps past the rates' one (search_stretch's proof_reach), all dimensionless: a reach tries
// kReachGrowth times the last step proved; it is tried, and a proved one shows that reaching
// pays, only when at least kReachPaid times the rates' step (a failed proof costs about as much
// as a proved one: reaching a little further does not pay); after a reach that falls back to
// the rates, 2, 4, ... up to 2^(kMaxReachWaitLog2 + 1) accepted steps wait before the next.
// Measured on Q2's proved search (instructions, callgrind) since the spiral's steps are proved in
// the frame turned with the head: 2 and 1.5 (as for the fixed frame's enclosures) 30.4e6, 1.5 and
// 1.2 28.7e6, 1.3 and 1.5 31.8e6, 1.7 and 1.1 29.8e6; the turnaround's contact proof about the
// same (5.58e9 and 5.54e9 for `dragon turnaround --prove`).
constexpr double kReachGrowth = 1.5;
constexpr double kReachPaid = 1.2;
constexpr int kMaxReachWaitLog2 = 4;

double head_radius(const Frame& f) { return norm(f.handles.front().pos); }

// The contact at head travel x, reported for `sim` (at its own head speed).
// Its evaluations are counted by the caller, over the stretches up to the contact's.
Contact make_contact(const Simulation& sim, double x, BroadPhase& broad) {
    Frame f = sim.frame_at_travel(x);
    const Clearance c = clearance(f, kMargin, broad);
    const double t = f.time;
    const double rounding = 2.0 * (std::nextafter(std::abs(t), INFINITY) - std::abs(t));
    Contact out{t, c.bench_a, c.bench_b, head_radius(f), c.point, std::move(f), 0,
                std::max(tol::travel / sim.scenario().head_speed, rounding)};
    out.travel = x;
    out.travel_tolerance = std::max(tol::travel, 2.0 * (std::nextafter(std::abs(x), INFINITY) - std::abs(x)));
    return out;
}

// Whether clearance(f, kMargin) <= 0, the sign a bracket and its bisection go by: told by
// overlap_of() but within rounding of touching, where the clearance itself decides.
bool touching(const Frame& f, Workspace& ws) {
    switch (overlap_of(f, ws)) {
        case Overlap::yes: return true;
        case Overlap::no: return false;
        case Overlap::unsure: break;
    }
    return clearance(f, kMargin, ws.broad).distance <= 0.0;
}

// How a stretch's search chooses and proves its steps.
struct StepRules {
    bool prove = true;        // prove each step by enclosures (swept_proof.hpp); false: the rate check alone
    bool check_ends = true;   // check the rate bounds at each step's end (false: tests of the assumption alone)
};

// Counts a step [from, to] (m of head travel) the search accepted, with what proved it.
void count_step(ContactProof& proof, const contact::StepProof& p, double from, double to) {
    if (p.verdict == contact::StepVerdict::proved) {
        ++proof.proved_steps;
        proof.least_gap = std::min(proof.least_gap, p.least_gap);
    } else {
        ++proof.unproved_steps;
        proof.unproved_travel += to - from;
    }
    proof.proved_to = to;
}

// The search over one stretch of head travel [x_from, x_to] (m), stepping `watched` (the benches
// that may touch, on the motion at 1 m/s, so that its times are head travel) and reporting the
// head travel of the contact; `steps` grows by the evaluations it makes, `proof` hears what it
// proved. A step covers at most kMaxTravel of head travel, and the contact is found to
// tol::travel.
//
// The rate bounds (approach()) choose each step's length, x to `next`; the step is accepted only
// when prove_step() proves, from the chain at its two ends, that no two benches touch anywhere
// in it. A step it cannot prove is taken again shorter (`proof_cap`): the rate bounds choose,
// the enclosures prove. A proved step needs no rate bound, so after proved steps the next may
// reach past the rates' step (`proof_reach`); one that is not proved falls back towards it. Where a link turns too far for the enclosures (not_monotone: near a
// tight turnaround), the step rests on the rate bounds checked at its end, and is counted as
// such. Near the contact the probe and the bisection locate it to tol::travel; the bracket they
// used is not proved by them, so the range from the last proved step to just before the contact
// is then proved the same way, step by step, and a contact found inside it restarts the
// bisection there. The contact then lies between the last proved travel and the reported one.
//
// The contact itself (the whole chain of `sim` there, and its closest pair) is made only for the
// stretch that wins (make_contact): a stretch after the first contact, which starts overlapping,
// costs one frame of the benches it watches and one overlap test.
template <class Stop>
std::optional<double> search_stretch(const Simulation& sim, const Simulation& watched, double x_from, double x_to,
                                     const StepObserver& on_step, const Stop& stop, int& steps, Workspace& ws,
                                     ContactProof& proof, const StepRules& rules) {
    const double max_step = kMaxTravel;    // m of head travel
    const double travel_tol = tol::travel;  // m of head travel
    const Path& path = watched.path();
    const BenchSpec& spec = watched.scenario().bench;
    Frame f;   // the chain at the travel being looked at
    Frame at;  // the chain at x, where the step being proved starts
    double x = x_from;  // m of head travel: everything before it is searched (and proved)
    proof.proved_from = proof.proved_to = x_from;
    StepRecord memory, seen;
    watched.frame_into(x, f);
    ++steps;
    // Starting with benches overlapping (a stretch after the first contact, which the workers
    // take first): its start, found without a whole evaluation's bounds (when unsure, the
    // evaluation decides).
    if (overlap_of(f, ws) == Overlap::yes) return x;
    Approach a = approach(f, x, max_step, memory, seen, false, ws);
    memory.swap(seen);
    if (a.clear.distance <= 0.0) return x;
    std::swap(at, f);
    // Which enclosures are tried first: the order that proved the last step.
    contact::Enclosures order = contact::Enclosures::either;
    const auto prove = [&](const Frame& end) {
        if (!rules.prove) return contact::StepProof{contact::StepVerdict::not_monotone, INFINITY, 0, 0};
        const contact::StepProof p = prove_step(path, spec, at, end, ws.swept, 0.0, order);
        if (p.verdict == contact::StepVerdict::proved) order = contact::tried_first_after(p);
        return p;
    };
    double retry_cap = INFINITY;  // m: after a broken curvature bound, retry shorter from x
    double proof_cap = INFINITY;  // m: the longest step the enclosures are expected to prove (halved when they fail)
    // m: how far the enclosures are expected to reach past the rates' step (a proved step's
    // length times kReachGrowth; 0 when the last step was not proved). A step the enclosures
    // prove needs no rate bound, so where the benches are far apart it may be longer than the
    // rates allow: on the turnaround's window, whose closest pair stays 0.28 m apart, the rates
    // choose steps of about 0.15 m and the enclosures prove steps several times as long.
    double proof_reach = 0.0;
    // Where the rates' step is about all the enclosures prove (the contest's Q2 near its
    // contact), reaching past it mostly fails: after each failure that falls back to the rates,
    // reaching waits for twice as many accepted steps as after the last (up to
    // 2^(kMaxReachWaitLog2 + 1)), until a reach pays.
    int reach_misses = 0;  // failures in a row that fell back to the rates
    int reach_wait = 0;    // accepted steps before reaching again

    while (x < x_to) {
        if (stop()) return std::nullopt;
        // A pair grazing within rounding of touching, closing too slowly to bound: contact now
        // (also when the step is below the resolution of x itself, late in a slow run).
        if (a.safe_step < travel_tol || x + a.safe_step == x) return x;
        // Bracket: a Newton probe on the closest pair once it is nearly touching, no farther
        // than any other pair is expected to touch.
        double x_hi = std::numeric_limits<double>::quiet_NaN();
        if (a.clear.distance < kProbeGap && a.rate < 0.0) {
            const double probe = std::min({x_to, x + 1.5 * a.clear.distance / -a.rate, x + a.others_step});
            watched.frame_into(probe, f);
            ++steps;
            if (touching(f, ws)) x_hi = probe;
        }
        if (std::isnan(x_hi)) {
            const bool reach = rules.prove && reach_wait == 0 && proof_reach >= kReachPaid * a.safe_step;
            const double wanted = std::max(a.safe_step, reach ? proof_reach : 0.0);  // m: the rates' step, or the reach
            const double next = std::min({x + wanted, x + retry_cap, x + proof_cap, x_to});
            // Whether the enclosures' cap chose this step (not next - x >= proof_cap: the sum's
            // rounding can make that false for the step the cap set, and the cap then never grows).
            const bool cap_chose = proof_cap <= std::min({wanted, retry_cap, x_to - x});
            // Whether the step goes past what the rates allow (it then stands on its proof alone):
            // by the lengths compared, not next - x (whose rounding can exceed the rates' step).
            const bool past_rates = std::min({wanted, retry_cap, proof_cap, x_to - x}) > a.safe_step;
            if (next <= x) break;
            watched.frame_into(next, f);
            ++steps;
            // The proof first (a step it fails is taken again shorter, its bounds not needed).
            const contact::StepProof p = prove(f);
            const bool proved = p.verdict == contact::StepVerdict::proved;
            if (!proved && past_rates) {
                // Longer than the rates allow and not proved: half as far (down to the rates'
                // own step).
                ++proof.subdivisions;
                proof_reach = 0.5 * (next - x);
                if (proof_reach < kReachPaid * a.safe_step) {
                    proof_reach = 0.0;
                    reach_wait = 2 << std::min(reach_misses, kMaxReachWaitLog2);
                    ++reach_misses;
                }
                continue;
            }
            const bool shorter_may = p.verdict == contact::StepVerdict::too_close ||
                                     (rules.prove && p.verdict == contact::StepVerdict::not_monotone &&
                                      next - x > kLeastEnclosedStep);
            if (shorter_may && next - x > travel_tol && overlap_of(f, ws) == Overlap::no) {
                // Not proved, and no contact at its end: the same start, half the step.
                ++proof.subdivisions;
                proof_cap = 0.5 * (next - x);
                continue;
            }
            const Approach b = approach(f, next, max_step, memory, seen, rules.check_ends, ws);
            // A proved step stands on its proof: the rates' promises over it do not matter.
            if (b.bound_broken && !proved && next - x > travel_tol) {
                // The rates turned faster than the step assumed: back to x, with a larger
                // curvature on record, and a shorter step.
                retry_cap = 0.25 * (next - x);
                memory.near.for_each([](PairMemory& m) { m.curvature *= 4.0; });
                continue;
            }
            if (b.clear.distance > 0.0) {
                if (p.verdict == contact::StepVerdict::too_close && next - x > travel_tol) {
                    // Not proved (its end within kSureGap of touching): the same start, half the step.
                    ++proof.subdivisions;
                    proof_cap = 0.5 * (next - x);
                    continue;
                }
                count_step(proof, p, x, next);
                // A step as long as the last one the enclosures proved: try a little longer next.
                if (proved && cap_chose) proof_cap *= kProofCapGrowth;
                proof_reach = proved ? kReachGrowth * (next - x) : 0.0;
                // A reach that paid (well past the rates' step) ends the waiting.
                if (proved && next - x >= kReachPaid * a.safe_step) reach_misses = 0;
                if (reach_wait > 0) --reach_wait;
                // One no length down to kLeastEnclosedStep could enclose rests on its rate bound:
                // the next is as long as the rates allow, not crept along at that length.
                if (p.verdict == contact::StepVerdict::not_monotone) proof_cap = INFINITY;
                memory.swap(seen);
                if (on_step) on_step(sim.time_of(x), sim.time_of(next));
                x = next;
                a = b;
                retry_cap = INFINITY;
                std::swap(at, f);
                continue;
            }
            x_hi = next;
        }
        for (;;) {
            // Bisection on [x, x_hi]: clearance > 0 at x, <= 0 at x_hi (only its sign: touching()).
            double lo = x, hi = x_hi;
            while (hi - lo > travel_tol) {
                const double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break;
                watched.frame_into(mid, f);
                ++steps;
                if (!touching(f, ws)) lo = mid; else hi = mid;
            }
            if (!rules.prove) {  // the bracket rests on the rate bounds too
                count_step(proof, {contact::StepVerdict::not_monotone, INFINITY, 0, 0}, x, lo);
                return hi;
            }
            // Prove [x, lo] step by step: the bisection only saw the clearance's sign at its
            // points. A step ending in contact is an earlier contact: bisect again before it.
            double h = lo - x;  // m: the next step to try
            bool earlier = false;
            while (x < lo) {
                if (stop()) return std::nullopt;
                // (Within an ulp of lo, x + h may round to x: the rest of the way at once.)
                const double y = x + h > x ? std::min(lo, x + h) : lo;
                watched.frame_into(y, f);
                ++steps;
                if (touching(f, ws)) {
                    x_hi = y;
                    earlier = true;
                    break;
                }
                const contact::StepProof p = prove(f);
                if (p.verdict == contact::StepVerdict::too_close) {
                    ++proof.subdivisions;
                    // Within the proof's slack of touching: the proof ends here, kFinalStep
                    // short of the contact at most where the steps it could still prove shrink
                    // below it.
                    if (y - x <= std::max(travel_tol, kFinalStep * (hi - x))) break;
                    h = 0.5 * (y - x);
                    continue;
                }
                count_step(proof, p, x, y);
                if (on_step) on_step(sim.time_of(x), sim.time_of(y));
                x = y;
                std::swap(at, f);
                // Twice the step proved, or most of what is left: where the enclosures are tight
                // the step's length is set by the gap the contact leaves at its end (closing
                // linearly to it), and each step leaves a sixteenth of the travel to go.
                h = std::min(2.0 * h, kFinalReach * (lo - x));
            }
            if (!earlier) return hi;
        }
    }
    return std::nullopt;
}

// What the proof of the untouched tail reads of the whole chain at each edge of the stretches
// (its handles' angles), made once for the two stretches that share it (by whichever worker asks
// first) instead of once for each. On the spiral only the angles are solved (solve_spiral_chain_angles:
// no points, speeds or benches), and kept: a few KB a search, where whole frames took about 1 MB.
class EdgeAngles {
public:
    EdgeAngles(const Simulation& unit, const std::vector<double>& edge)
        : unit_(unit), edge_(edge), angles_(edge.size()), made_(edge.size()) {}
    const ChainAngles& at(size_t k, Frame& scratch) {
        std::call_once(made_[k], [&] {
            // The edge, m of head travel: on the motion at 1 m/s also its time, s.
            const double x = edge_[k];
            unit_.require_valid(x, Key::time);  // as a frame there would
            ChainAngles& a = angles_[k];
            a.time = x;
            if (!solve_spiral_chain_angles(unit_.path(), unit_.scenario().bench, unit_.head_arc(x), a.theta)) {
                unit_.frame_into(x, scratch);
                a = chain_angles(scratch);
            }
        });
        return angles_[k];
    }
    double travel(size_t k) const { return edge_[k]; }  // m: edge k's head travel

private:
    const Simulation& unit_;
    const std::vector<double>& edge_;
    std::vector<ChainAngles> angles_;
    std::vector<std::once_flag> made_;
};

// The benches a search over stretch k of `unit` (the motion at 1 m/s) must watch: while the
// whole chain coils in along one spiral (the plain spiral; the turnaround's way in, before the
// head reaches the turn) only the leading ones that may touch (core/untouched_tail.hpp),
// elsewhere all of them. The head's place at the stretch's end tells: every place behind it
// lies on that spiral too.
Simulation watched_over(const Simulation& unit, EdgeAngles& edges, size_t k, bool skip_untouched_tail, Frame& scratch) {
    if (!skip_untouched_tail) return unit;
    const Path& path = unit.path();
    const Spiral* spiral = path.coil_in_spiral(path.at_arc(unit.head_arc(edges.travel(k + 1))).place);
    if (!spiral) return unit;
    const ChainAngles& first = edges.at(k, scratch);
    const ChainAngles& last = edges.at(k + 1, scratch);
    return unit.leading(benches_that_may_touch(*spiral, unit.scenario().bench, first, last));
}

// The range of travel [x_from, x_to] in stretches: cut at every multiple of kStretchTravel, so
// that a stretch is the same (and its search takes the same steps) whatever range holds it, and
// whatever worker searches it.
std::vector<double> stretch_edges(double x_from, double x_to) {
    std::vector<double> edges{x_from};
    for (double k = std::floor(x_from / kStretchTravel) + 1.0; k * kStretchTravel < x_to; ++k)
        if (k * kStretchTravel > x_from) edges.push_back(k * kStretchTravel);
    edges.push_back(x_to);
    return edges;
}

}  // namespace

// Each stretch's search is exact for its own range, and a stretch that starts with benches
// overlapping reports its start: the overlap began in an earlier stretch, which then reports
// that contact itself. So the first contact is the one of the earliest stretch reporting any.
// The executor's workers take the stretches latest first (the one holding the contact usually
// costs most: short steps, then the bisection); stretches after a contact already found are
// abandoned, and every stretch before it runs to its end. The stretches do not depend on the
// workers, so neither does the answer, nor the count of evaluations.
std::optional<Contact> first_contact_travel(const Simulation& sim, double x_from, double x_to,
                                            const ContactSearchOptions& options) {
    // Both ends within the valid motion (the range between them then is too); searched here,
    // once, so that the frames below find it known.
    sim.require_valid_travel(x_from, Key::from);
    sim.require_valid_travel(x_to, Key::to);
    const Simulation unit = sim.at_speed(1.0);
    InlineExecutor in_order(options.executor);
    Executor& ex = options.on_step ? in_order : executor_or(options.executor, in_order);
    const std::vector<double> edge = x_to > x_from ? stretch_edges(x_from, x_to) : std::vector<double>{x_from, x_from};
    const size_t chunks = edge.size() - 1;
    std::vector<std::optional<double>> found(chunks);  // the travel of each stretch's contact
    std::vector<int> steps(chunks, 0);
    std::vector<ContactProof> proofs(chunks);  // what each stretch's search proved
    std::vector<Workspace> ws(static_cast<size_t>(ex.workers()));
    for (Workspace& w : ws) w.rate_safety = options.rate_safety;
    const StepRules rules{options.prove_steps, options.check_step_ends};
    std::atomic<size_t> winner{chunks};
    EdgeAngles edge_angles(unit, edge);
    const bool serial = ex.workers() == 1;
    auto search = [&](size_t k, int worker) {
        if (winner.load() < k) return;
        check_stop(ex);
        Workspace& mine = ws[static_cast<size_t>(worker)];
        const Simulation watched = watched_over(unit, edge_angles, k, options.skip_untouched_tail, mine.frame);
        try {
            found[k] = search_stretch(sim, watched, edge[k], edge[k + 1], options.on_step,
                                      [&] { return winner.load(std::memory_order_relaxed) < k; }, steps[k], mine,
                                      proofs[k], rules);
        } catch (...) {
            winner = 0;  // stop the others at their next step; the executor rethrows this
            throw;
        }
        if (found[k]) {
            size_t w = winner.load();
            while (k < w && !winner.compare_exchange_weak(w, k)) {
            }
        }
    };
    if (serial) {
        for (size_t k = 0; k < chunks && winner.load() == chunks; ++k) search(k, 0);
    } else {
        ex.parallel_for(chunks, [&](size_t item, int worker) { search(chunks - 1 - item, worker); });
    }
    const size_t w = winner.load();
    // What the stretches up to the contact's (every stretch, without one) proved, in order.
    ContactProof proved;
    proved.proved_from = proved.proved_to = x_from;
    for (size_t k = 0; k < chunks && k <= w; ++k) {
        const ContactProof& p = proofs[k];
        proved.proved_steps += p.proved_steps;
        proved.subdivisions += p.subdivisions;
        proved.unproved_steps += p.unproved_steps;
        proved.unproved_travel += p.unproved_travel;
        proved.least_gap = std::min(proved.least_gap, p.least_gap);
        proved.proved_to = p.proved_to;
    }
    if (options.prove_steps) {
        // The steps' proofs assume the valid motion over the range (Proposition 1's premise):
        // proved here by the walk asked to prove every step, up to the contact (or the range's end).
        proved.motion_checked = true;
        const double x_end = w == chunks ? x_to : *found[w];
        find_jam(unit.path(), unit.scenario().bench, unit.head_arc(0.0), 1.0, x_from, x_end, &proved.motion, {true});
    }
    if (options.proof) *options.proof = proved;
    if (w == chunks) return std::nullopt;
    Contact c = make_contact(sim, *found[w], ws.front().broad);
    c.steps = 0;
    for (size_t k = 0; k <= w; ++k) c.steps += steps[k];
    c.proof = proved;
    c.enclosure_lo = proved.proved_to;
    c.enclosure_hi = *found[w];
    c.enclosure_time_lo = sim.time_of(c.enclosure_lo);
    c.enclosure_time_hi = sim.time_of(c.enclosure_hi);
    return c;
}

std::optional<Contact> first_contact(const Simulation& sim, double t_from, double t_to,
                                     const ContactSearchOptions& options) {
    sim.require_valid(t_from, Key::from);
    sim.require_valid(t_to, Key::to);
    return first_contact_travel(sim, sim.travel_within(t_from), sim.travel_within(t_to), options);
}

}  // namespace dragon
