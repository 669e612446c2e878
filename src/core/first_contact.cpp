// Q2: the first moment two non-adjacent benches touch.
//
// The search runs in head travel (m from the head's place at t = 0), on the motion at 1 m/s:
// the chain's shape depends on the travel alone, so the contact found is the same, bit for bit,
// at any head speed, and its time is travel / speed.
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
// bisection to tol::travel.
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

// The search over one stretch of travel, stepping `watched` (the benches that may touch, on the
// motion at 1 m/s, so that its times are head travel) and reporting the head travel of the
// contact; `steps` grows by the evaluations it makes. A step covers at most kMaxTravel of head
// travel, and the contact is found to tol::travel. The contact itself (the whole chain of `sim`
// there, and its closest pair) is made only for the stretch that wins (make_contact): a stretch
// after the first contact, which starts overlapping, costs one frame of the benches it watches
// and one overlap test.
template <class Stop>
std::optional<double> search_stretch(const Simulation& sim, const Simulation& watched, double t_from, double t_to,
                                     const StepObserver& on_step, const Stop& stop, int& steps, Workspace& ws) {
    const double max_step = kMaxTravel;
    const double time_tol = tol::travel;
    Frame f;
    double t = t_from;
    StepRecord memory, seen;
    watched.frame_into(t, f);
    ++steps;
    // Starting with benches overlapping (a stretch after the first contact, which the workers
    // take first): its start, found without a whole evaluation's bounds (when unsure, the
    // evaluation decides).
    if (overlap_of(f, ws) == Overlap::yes) return t;
    Approach a = approach(f, t, max_step, memory, seen, false, ws);
    memory.swap(seen);
    if (a.clear.distance <= 0.0) return t;
    double retry_cap = INFINITY;  // after a broken curvature bound, retry shorter from t

    while (t < t_to) {
        if (stop()) return std::nullopt;
        // A pair grazing within rounding of touching, closing too slowly to bound: contact now
        // (also when the step is below the resolution of t itself, late in a slow run).
        if (a.safe_step < time_tol || t + a.safe_step == t) return t;
        // Bracket: a Newton probe on the closest pair once it is nearly touching, no farther
        // than any other pair could touch (the bisection below sees only the clearance's sign,
        // and would pass over another pair's contact that opens and closes inside its bracket).
        double t_hi = std::numeric_limits<double>::quiet_NaN();
        if (a.clear.distance < kProbeGap && a.rate < 0.0) {
            const double probe = std::min({t_to, t + 1.5 * a.clear.distance / -a.rate, t + a.others_step});
            watched.frame_into(probe, f);
            ++steps;
            if (touching(f, ws)) t_hi = probe;
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
                memory.near.for_each([](PairMemory& m) { m.curvature *= 4.0; });
                continue;
            }
            memory.swap(seen);
            if (b.clear.distance > 0.0) {
                if (on_step) on_step(sim.time_of(t), sim.time_of(next));
                t = next;
                a = b;
                retry_cap = INFINITY;
                continue;
            }
            t_hi = next;
        }
        // Bisection on [t, t_hi]: clearance > 0 at t, <= 0 at t_hi (only its sign: touching()).
        double lo = t, hi = t_hi;
        while (hi - lo > time_tol) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            watched.frame_into(mid, f);
            ++steps;
            if (!touching(f, ws)) lo = mid; else hi = mid;
        }
        return hi;
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
            const double t = edge_[k];
            unit_.require_valid(t, Key::time);  // as a frame there would
            ChainAngles& a = angles_[k];
            a.time = t;
            if (!solve_spiral_chain_angles(unit_.path(), unit_.scenario().bench, unit_.head_arc(t), a.theta)) {
                unit_.frame_into(t, scratch);
                a = chain_angles(scratch);
            }
        });
        return angles_[k];
    }

private:
    const Simulation& unit_;
    const std::vector<double>& edge_;
    std::vector<ChainAngles> angles_;
    std::vector<std::once_flag> made_;
};

// The benches a search over stretch k of `unit` (the motion at 1 m/s) must watch: on the plain
// spiral only the leading ones that may touch (core/untouched_tail.hpp), elsewhere all of them.
Simulation watched_over(const Simulation& unit, EdgeAngles& edges, size_t k, bool skip_untouched_tail, Frame& scratch) {
    const auto* spiral = dynamic_cast<const Spiral*>(&unit.path());
    if (!spiral || !skip_untouched_tail) return unit;
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
    std::vector<Workspace> ws(static_cast<size_t>(ex.workers()));
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
                                      [&] { return winner.load(std::memory_order_relaxed) < k; }, steps[k], mine);
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
    if (w == chunks) return std::nullopt;
    Contact c = make_contact(sim, *found[w], ws.front().broad);
    c.steps = 0;
    for (size_t k = 0; k <= w; ++k) c.steps += steps[k];
    return c;
}

std::optional<Contact> first_contact(const Simulation& sim, double t_from, double t_to,
                                     const ContactSearchOptions& options) {
    sim.require_valid(t_from, Key::from);
    sim.require_valid(t_to, Key::to);
    return first_contact_travel(sim, sim.travel_within(t_from), sim.travel_within(t_to), options);
}

}  // namespace dragon
