// Q2: the first moment two non-adjacent benches touch.
//
// Stepping: at time t every pair of benches has separation g_ij > 0 and, from the benches'
// exact rigid-body velocity fields, a bound L_ij on how fast g_ij can shrink now. Advancing by
//     tau = min_ij g_ij / (kSafety L_ij)
// cannot skip a contact as long as the true closing speed stays below kSafety times the bound
// over the step, which holds with a wide margin because the benches' velocities change slowly
// over a step of at most kMaxTravel of head travel. Pairs within the broad phase's margin M get
// their own bounds (and second-order ones near grazing passes, checked at the next evaluation);
// pairs beyond it are bounded group by group (far_pairs_step); benches or groups on different
// turns may instead take a bound from their radii about the centre, which neighbouring turns
// sliding past each other do not shrink (radial_step). Collide-separate-collide windows
// are therefore never stepped over, unlike one bisection over the whole run; the test
// Q2.EveryStepDeclaredSafeIsSafe samples inside every step, on runs with such a window. Near
// the contact a Newton probe on the closest pair brackets the root, which is then refined by
// bisection to tol::contact_time.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

#include "core/contact_step.hpp"
#include "core/untouched_tail.hpp"
#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"
#include "dragon/executor.hpp"

namespace dragon {

namespace {

using contact::Approach;
using contact::kMargin;
using contact::kMaxTravel;
using contact::kProbeGap;
using contact::Memory;
using contact::PairMemory;
using contact::Workspace;

// Head travel one proof of the untouched tail covers (untouched_tail.hpp): a shorter stretch
// proves more of the tail untouched (the chain's reach is judged at its innermost moment), for
// two more frames and a restart of the stepping. Measured on Q3's runs: 10 m watches about
// 8 of the contest's 223 benches on average, against 30 for one proof of the whole run.
constexpr double kStretchTravel = 10.0;  // m

double head_radius(const Frame& f) { return norm(f.handles.front().pos); }

Contact make_contact(const Simulation& sim, double t, int steps, double time_tol, BroadPhase& broad) {
    Frame f = sim.frame(t);
    const Clearance c = clearance(f, kMargin, broad);
    const double rounding = 2.0 * (std::nextafter(t, INFINITY) - t);
    return {t, c.bench_a, c.bench_b, head_radius(f), c.point, std::move(f), steps, std::max(time_tol, rounding)};
}

// The search over one stretch, stepping `watched` (the benches that may touch) and reporting
// the contact with the whole chain of `sim`; `steps` grows by the evaluations it makes.
template <class Stop>
std::optional<Contact> search_stretch(const Simulation& sim, const Simulation& watched, double t_from, double t_to,
                                      const StepObserver& on_step, const Stop& stop, int& steps, Workspace& ws) {
    // Everything scales with the head's speed: the chain at speed v is the chain at 1 m/s with
    // time divided by v. A step covers at most kMaxTravel of head travel, and the contact time
    // is found to tol::contact_time and to at most that many metres of head travel (so 1e-9 s at
    // the contest's 1 m/s, and proportionally finer for a faster dragon).
    const double speed = sim.scenario().head_speed;
    const double max_step = kMaxTravel / speed;
    const double time_tol = tol::contact_time * std::min(1.0, 1.0 / speed);
    Frame f;
    double t = t_from;
    Memory memory, seen;
    watched.frame_into(t, f);
    Approach a = approach(f, t, max_step, memory, seen, false, ws);
    memory.swap(seen);
    ++steps;
    if (a.clear.distance <= 0.0) return make_contact(sim, t, steps, time_tol, ws.broad);
    double retry_cap = INFINITY;  // after a broken curvature bound, retry shorter from t

    while (t < t_to) {
        if (stop()) return std::nullopt;
        // A pair grazing within rounding of touching, closing too slowly to bound: contact now
        // (also when the step is below the resolution of t itself, late in a slow run).
        if (a.safe_step < time_tol || t + a.safe_step == t) return make_contact(sim, t, steps, time_tol, ws.broad);
        // Bracket: a Newton probe on the closest pair once it is nearly touching, no farther
        // than any other pair could touch (the bisection below sees only the clearance's sign,
        // and would pass over another pair's contact that opens and closes inside its bracket).
        double t_hi = std::numeric_limits<double>::quiet_NaN();
        if (a.clear.distance < kProbeGap && a.rate < 0.0) {
            const double probe = std::min({t_to, t + 1.5 * a.clear.distance / -a.rate, t + a.others_step});
            watched.frame_into(probe, f);
            ++steps;
            if (clearance(f, kMargin, ws.broad).distance <= 0.0) t_hi = probe;
        }
        if (std::isnan(t_hi)) {
            const double next = std::min({t + a.safe_step, t + retry_cap, t_to});
            if (next <= t) break;
            watched.frame_into(next, f);
            ++steps;
            const Approach b = approach(f, next, max_step, memory, seen, true, ws);
            if (b.bound_broken && next - t > time_tol) {
                // The rates turned faster than the step assumed: back to t, with a larger
                // curvature on record, and a shorter step.
                retry_cap = 0.25 * (next - t);
                memory.for_each([](PairMemory& m) { m.curvature *= 4.0; });
                continue;
            }
            memory.swap(seen);
            if (b.clear.distance > 0.0) {
                if (on_step) on_step(t, next);
                t = next;
                a = b;
                retry_cap = INFINITY;
                continue;
            }
            t_hi = next;
        }
        // Bisection on [t, t_hi]: clearance > 0 at t, <= 0 at t_hi.
        double lo = t, hi = t_hi;
        while (hi - lo > time_tol) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            watched.frame_into(mid, f);
            ++steps;
            if (clearance(f, kMargin, ws.broad).distance > 0.0) lo = mid; else hi = mid;
        }
        return make_contact(sim, hi, steps, time_tol, ws.broad);
    }
    return std::nullopt;
}

// The benches a search over [t0, t1] must watch: on the plain spiral only the leading ones that
// may touch (core/untouched_tail.hpp), elsewhere all of them.
Simulation watched_over(const Simulation& sim, double t0, double t1) {
    const auto* spiral = dynamic_cast<const Spiral*>(&sim.path());
    if (!spiral) return sim;
    return sim.leading(benches_that_may_touch(*spiral, sim.scenario().bench, sim.frame(t0), sim.frame(t1)));
}

// The search over one range, in stretches of at most kStretchTravel of head travel, each with
// its own watched benches. `stop()` is asked once per step: true abandons the search (a
// contact was found in an earlier range). `steps` counts the evaluations; `ws` is this search's
// own scratch.
template <class Stop>
std::optional<Contact> search_range(const Simulation& sim, double t_from, double t_to, const ContactSearchOptions& options,
                                    const Stop& stop, int& steps, Workspace& ws) {
    steps = 0;
    if (!options.skip_untouched_tail)
        return search_stretch(sim, sim, t_from, t_to, options.on_step, stop, steps, ws);
    const double stretch = kStretchTravel / sim.scenario().head_speed;
    const double count = std::max(1.0, std::ceil((t_to - t_from) / stretch));
    for (double k = 0; k < count; ++k) {
        const double a = k == 0 ? t_from : t_from + (t_to - t_from) * (k / count);
        const double b = k + 1 == count ? t_to : t_from + (t_to - t_from) * ((k + 1) / count);
        if (std::optional<Contact> c = search_stretch(sim, watched_over(sim, a, b), a, b, options.on_step, stop, steps, ws))
            return c;
        if (stop()) return std::nullopt;
    }
    return std::nullopt;
}

}  // namespace

// The range is cut into chunks searched by the executor's workers, latest first. Each chunk's
// search is exact for its own range, and a chunk that starts with benches overlapping reports its
// start: the overlap began in an earlier chunk, which then reports that contact itself. So the
// first contact is the one of the earliest chunk reporting any; chunks after it are abandoned.
// Every chunk before it has run to its end, so the answer (and the evaluation count) does not
// depend on how the workers were scheduled, only on how many there are.
std::optional<Contact> first_contact(const Simulation& sim, double t_from, double t_to,
                                     const ContactSearchOptions& options) {
    // Both ends within the valid motion (the range between them then is too); searched here,
    // once, so that the frames below find it known.
    sim.require_valid(t_from, "time range start");
    sim.require_valid(t_to, "time range end");
    InlineExecutor in_order;
    Executor& ex = options.on_step ? in_order : executor_or_default(options.executor);
    auto never = [] { return false; };
    if (ex.workers() == 1 || !(t_to > t_from)) {
        int steps = 0;
        Workspace ws;
        return search_range(sim, t_from, t_to, options, never, steps, ws);
    }
    const size_t chunks = 8 * static_cast<size_t>(ex.workers());
    std::vector<double> edge(chunks + 1);
    for (size_t k = 0; k <= chunks; ++k)
        edge[k] = k == chunks ? t_to : t_from + (t_to - t_from) * static_cast<double>(k) / static_cast<double>(chunks);
    std::vector<std::optional<Contact>> found(chunks);
    std::vector<int> steps(chunks, 0);
    std::vector<Workspace> ws(static_cast<size_t>(ex.workers()));
    std::atomic<size_t> winner{chunks};
    ContactSearchOptions chunk_options = options;
    chunk_options.on_step = {};
    // Latest chunk first: the one holding the contact usually costs most (short steps, then the
    // bisection), so it starts early, and the ones after it start overlapping and end at once.
    ex.parallel_for(chunks, [&](size_t item, int worker) {
        const size_t k = chunks - 1 - item;
        if (winner.load() < k) return;
        try {
            found[k] = search_range(sim, edge[k], edge[k + 1], chunk_options,
                                    [&] { return winner.load(std::memory_order_relaxed) < k; }, steps[k],
                                    ws[static_cast<size_t>(worker)]);
        } catch (...) {
            winner = 0;  // stop the others at their next step; the executor rethrows this
            throw;
        }
        if (found[k]) {
            size_t w = winner.load();
            while (k < w && !winner.compare_exchange_weak(w, k)) {
            }
        }
    });
    const size_t w = winner.load();
    if (w == chunks) return std::nullopt;
    Contact c = std::move(*found[w]);
    c.steps = 0;
    for (size_t k = 0; k <= w; ++k) c.steps += steps[k];
    return c;
}

}  // namespace dragon
