// Q3: the smallest pitch with which the head reaches the turning-space boundary collision-free.
#include <cmath>
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <limits>
#include <mutex>
#include <vector>

#include <fmt/format.h>

#include "golden_section.hpp"
#include "make_path.hpp"
#include "pitch_proof.hpp"
#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"

namespace dragon {

namespace {

// Narrowing a change of feasibility: the touching pair's closest approach is looked for within
// kApproachWindow of its contact time (the window closes where the contact was, within seconds
// for nearby pitches), on kApproachSamples samples then by golden section to kApproachTime
// (the approach is flat to ~1e-14 m that close to its minimum); regula falsi on the pitch runs
// at most kFalsiRounds rounds of kFalsiSteps steps before the k-section takes over.
constexpr double kApproachWindow = 5.0;  // s
constexpr int kApproachSamples = 40;
constexpr double kApproachTime = 1e-7;   // s
constexpr int kFalsiRounds = 4;
constexpr int kFalsiSteps = 60;
// Interior points the k-section tests each round, whatever the executor's size: the same pitches
// are run on one worker or many, so the answer does not depend on how many there are (3 points
// quarter the bracket: a round takes 2 runs' time on 2 workers, as two bisections would).
constexpr int kSectionPoints = 3;

// Where the head starts on the plain spiral at this pitch: r = b theta.
double start_radius(double pitch, double start_turn) { return Spiral(pitch).b() * kTwoPi * start_turn; }

// The error of a pitch whose run cannot start: the head would start inside the turning space.
InputError starts_inside(Key field, double pitch, double start_turn, double turn_radius) {
    return InputError(field, error_value(pitch),
                      fmt::format("it puts the head's start (radius {:.4f} m) inside the turning space (radius {} m); "
                                  "a pitch above {} m starts the head outside it",
                                  start_radius(pitch, start_turn), turn_radius, turn_radius / start_turn));
}

}  // namespace

namespace {

// The run to the boundary at one pitch, on the calling thread, stopping when `outer` asks.
BoundaryRun run_inline(Scenario s, double pitch, const Executor* outer) {
    s.path.kind = PathKind::spiral;
    s.path.pitch = pitch;
    const Simulation sim(s);
    if (start_radius(pitch, s.path.start_turn) <= s.path.turn_radius)
        throw starts_inside(Key::pitch, pitch, s.path.start_turn, s.path.turn_radius);
    const double t_end = boundary_time(sim);
    BoundaryRun run;
    run.jam = sim.jam_before(t_end);
    // On this thread: min_pitch runs its pitches in parallel already.
    InlineExecutor here(outer);
    run.contact = first_contact(sim, 0.0, run.jam ? run.jam->time : t_end, {.on_step = {}, .executor = &here});
    if (run.contact) run.jam.reset();  // the collision comes first
    return run;
}

}  // namespace

BoundaryRun run_to_boundary(Scenario s, double pitch) { return run_inline(std::move(s), pitch, nullptr); }

std::optional<Contact> contact_before_boundary(Scenario s, double pitch) { return run_to_boundary(std::move(s), pitch).contact; }

namespace {

// What one run to the boundary found: feasible, or the first contact (time and pair), or the
// end of the valid motion before the boundary.
struct Probe {
    bool feasible = false;
    double time = 0.0;
    int bench_a = 0, bench_b = 0;
    std::optional<Jam> jam;
};

// Feasibility of several pitches at once, spread over the executor's workers: each pitch is an
// independent run of the dragon to the boundary. Every run is made, and a run's error is kept
// with its pitch: the one thrown is that of the smallest pitch that failed, the one a serial
// scan would meet first, whichever thread finished first.
std::vector<Probe> probe_at(const Scenario& s, Executor& ex, const std::vector<double>& pitches,
                            const WorkProgress& progress = {}) {
    std::vector<Probe> out(pitches.size());
    std::vector<std::exception_ptr> failed(pitches.size());
    std::mutex progress_lock;
    std::int64_t done = 0;  // under progress_lock: the callback hears one worker at a time
    ex.parallel_for(pitches.size(), [&](size_t k, int) {
        try {
            const BoundaryRun run = run_inline(s, pitches[k], &ex);
            if (run.contact) out[k] = Probe{false, run.contact->time, run.contact->bench_a, run.contact->bench_b, {}};
            else if (run.jam) out[k] = Probe{false, run.jam->time, 0, 0, run.jam};
            else out[k] = Probe{true, 0.0, 0, 0, {}};
        } catch (...) {
            failed[k] = std::current_exception();
        }
        if (progress) {
            const std::lock_guard<std::mutex> hold(progress_lock);
            progress(++done, static_cast<std::int64_t>(pitches.size()));
        }
    });
    std::vector<size_t> order(pitches.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return pitches[a] < pitches[b]; });
    for (size_t k : order)
        if (failed[k]) std::rethrow_exception(failed[k]);
    return out;
}

// Narrows [a, b] (feasible at exactly one end) to tol::pitch by k-section: each round tests
// kSectionPoints interior points (in parallel), keeping the sub-interval where feasibility changes.
double k_section(const Scenario& s, Executor& ex, double a, double b, bool feasible_at_a) {
    constexpr size_t points = kSectionPoints;
    while (b - a > tol::pitch) {
        std::vector<double> probe;
        for (size_t k = 1; k <= points; ++k) probe.push_back(a + (b - a) * static_cast<double>(k) / static_cast<double>(points + 1));
        if (probe.front() <= a || probe.back() >= b) break;
        const std::vector<Probe> ok = probe_at(s, ex, probe);
        double na = a, nb = b;
        for (size_t k = 0; k < probe.size(); ++k) {
            if (ok[k].feasible == feasible_at_a) {
                na = probe[k];
            } else {
                nb = probe[k];
                break;
            }
        }
        a = na;
        b = nb;
    }
    return feasible_at_a ? a : b;  // keep the feasible side of the cut
}

// The closest approach of benches a and b over [t0, t1] at pitch p: a scan of kApproachSamples,
// then golden-section search around the smallest sample, to kApproachTime.
double closest_approach(const Scenario& s, double pitch, int a, int b, double t0, double t1) {
    Scenario q = s;
    q.path.pitch = pitch;
    const Simulation sim(q);
    t1 = std::min(t1, sim.end_time());
    if (const std::optional<Jam> j = sim.jam_before(t1)) t1 = j->time;
    // Only the chain up to the later of the two benches: its leading handles are the whole
    // chain's, bit for bit (the chain is solved from the head back).
    const Simulation lead = sim.leading(std::max(a, b));
    Frame f;
    auto gap = [&](double t) {
        lead.frame_into(t, f);
        return separation(f.benches[static_cast<size_t>(a - 1)], f.benches[static_cast<size_t>(b - 1)]).distance;
    };
    constexpr int kSamples = kApproachSamples;
    double best_t = t0, best = INFINITY;
    for (int k = 0; k <= kSamples; ++k) {
        const double t = t0 + (t1 - t0) * k / kSamples;
        if (const double g = gap(t); g < best) best = g, best_t = t;
    }
    double lo = std::max(t0, best_t - (t1 - t0) / kSamples), hi = std::min(t1, best_t + (t1 - t0) / kSamples);
    return std::min(best, golden_min(gap, lo, hi, kApproachTime).second);
}

// Narrows a change of feasibility between grid points. Where it is a contact window closing
// (the pair that touches at the infeasible end passes at a distance at the feasible end), the
// pitch at which that pair's closest approach is zero is found by regula falsi (Illinois) on a
// smooth function: a few cheap local searches instead of full runs. Full runs at that pitch
// plus and minus half the tolerance then decide: a confirmed cut is returned; a run still
// colliding (another pair's window closes later) becomes the new infeasible end, with its pair.
// Anything else, and after a few rounds, the k-section decides.
double refine_cut(const Scenario& s, Executor& ex, double a, double b, const Probe& at_a, const Probe& at_b) {
    const bool feasible_at_a = at_a.feasible;
    Probe hit = feasible_at_a ? at_b : at_a;
    double p_in = feasible_at_a ? b : a, p_ok = feasible_at_a ? a : b;
    const double dir = p_ok > p_in ? 1.0 : -1.0;
    // A change from a jam is no contact window: only the k-section can narrow it.
    for (int round = 0; round < kFalsiRounds && !hit.jam; ++round) {
        const double t0 = std::max(0.0, hit.time - kApproachWindow), t1 = hit.time + kApproachWindow;
        auto closest = [&](double p) { return closest_approach(s, p, hit.bench_a, hit.bench_b, t0, t1); };
        double lo = p_in, hi = p_ok, g_lo = closest(lo), g_hi = closest(hi);
        if (!(g_lo < 0.0 && g_hi > 0.0)) break;
        int side = 0;
        for (int it = 0; it < kFalsiSteps && std::abs(hi - lo) > 0.1 * tol::pitch; ++it) {
            const double p = lo - g_lo * (hi - lo) / (g_hi - g_lo);
            const double g = closest(p);
            if (g == 0.0) { lo = hi = p; break; }
            if (g < 0.0) {
                lo = p, g_lo = g;
                if (side == -1) g_hi *= 0.5;
                side = -1;
            } else {
                hi = p, g_hi = g;
                if (side == +1) g_lo *= 0.5;
                side = +1;
            }
        }
        const double mid = 0.5 * (lo + hi);
        const double ok_side = mid + dir * 0.5 * tol::pitch, in_side = mid - dir * 0.5 * tol::pitch;
        if ((ok_side - p_in) * dir <= 0.0 || (p_ok - ok_side) * dir <= 0.0) break;
        const std::vector<Probe> check = probe_at(s, ex, {ok_side, in_side});
        if (check[0].feasible && !check[1].feasible) return ok_side;
        if (check[0].feasible) break;  // feasible on both sides of this pair's cut: not the one
        p_in = ok_side;                 // still infeasible here: another window closes later
        hit = check[0];
    }
    return k_section(s, ex, feasible_at_a ? a : p_in, feasible_at_a ? p_in : b, feasible_at_a);
}

}  // namespace

// For the contest's dragon, a 1 mm scan of 0.35..0.55 m (tests) and a 0.1 mm one (README) find
// no window the default grid misses.
double pitch_grid_steps(double lo, double hi, double grid) { return std::ceil((hi - lo) / grid * (1.0 - 1e-12)); }

MinPitch min_pitch(const Scenario& scenario, double lo, double hi, const MinPitchOptions& options) {
    const double grid = options.grid;
    InlineExecutor serial;
    Executor& ex = executor_or(options.executor, serial);
    // What every run reads but the pitch, which the search sets.
    validate(scenario, value::bench | value::head_speed | value::start_turn | value::turn_radius);
    // Whether a run collides depends on the head's travel, not its speed: the runs go at 1 m/s
    // (the same pitches, bit for bit, at any head speed), and a jam's time is scaled at the end.
    Scenario s = scenario;
    s.head_speed = 1.0;
    constexpr double kMaxPitch = 1e3;  // m, the largest pitch validate() allows
    if (!(hi <= kMaxPitch))
        throw InputError(Key::hi, error_value(hi), fmt::format("a pitch is at most {} m", kMaxPitch));
    if (!(lo > s.bench.width) || !(hi > lo))
        throw InputError(fmt::format("pitch search range [{}, {}] is not allowed: it needs width {} < lo < hi",
                                     lo, hi, s.bench.width));
    // The runs start with the head outside the turning space: from a pitch above this on (the
    // start's radius grows with the pitch), so a range starting there holds no pitch that cannot start.
    const double lowest = std::max(s.bench.width, s.path.turn_radius / s.path.start_turn);
    if (start_radius(lo, s.path.start_turn) <= s.path.turn_radius)
        throw starts_inside(Key::lo, lo, s.path.start_turn, s.path.turn_radius);
    if (!(grid > 0.0) || !std::isfinite(grid))
        throw InputError(Key::grid, error_value(grid), "give a pitch spacing above 0, in m");
    const double steps = pitch_grid_steps(lo, hi, grid);
    if (steps > kMaxPitchGridSteps)
        throw InputError(Key::grid, error_value(grid),
                         fmt::format("it makes {:.3g} grid steps over [{}, {}]; at most {} (a grid of at least {:.2g} m)",
                                     steps, lo, hi, kMaxPitchGridSteps, (hi - lo) / kMaxPitchGridSteps));
    MinPitch out{};
    out.search_lo = lo;
    out.search_hi = hi;
    out.lowest = lowest;
    out.lowest_is_start = s.path.turn_radius / s.path.start_turn >= s.bench.width;
    // Scan on a grid, then refine each change of feasibility.
    const int n = std::max(2, static_cast<int>(steps));
    std::vector<double> pitches(static_cast<size_t>(n + 1));
    for (int k = 0; k <= n; ++k) pitches[static_cast<size_t>(k)] = k == n ? hi : lo + (hi - lo) * k / n;
    const std::vector<Probe> ok = probe_at(s, ex, pitches, options.progress);
    std::vector<double> cuts;
    for (size_t k = 0; k + 1 < pitches.size(); ++k)
        if (ok[k].feasible != ok[k + 1].feasible)
            cuts.push_back(refine_cut(s, ex, pitches[k], pitches[k + 1], ok[k], ok[k + 1]));
    double start = lo;
    bool state = ok.front().feasible;
    for (double c : cuts) {
        out.intervals.push_back({start, c, state});
        start = c;
        state = !state;
    }
    out.intervals.push_back({start, hi, state});
    out.grid = (hi - lo) / n;
    out.pitch = std::numeric_limits<double>::quiet_NaN();
    // The smallest feasible pitch is where the first feasible interval begins, if that is a
    // change inside the range; a feasible low end says only that it lies at or below the range.
    if (out.intervals.front().feasible) {
        out.below_range = true;
    } else {
        for (const PitchInterval& iv : out.intervals)
            if (iv.feasible) { out.pitch = iv.lo; break; }
        out.above_range = std::isnan(out.pitch);
    }
    for (size_t k = pitches.size(); k-- > 0;)
        if (ok[k].jam) { out.jam = PitchJam{pitches[k], *ok[k].jam}; break; }
    if (out.jam) {
        Jam& j = out.jam->jam;
        j.time = j.travel / scenario.head_speed;
        j.tolerance = std::max(j.travel_tolerance / scenario.head_speed,
                               std::abs(std::nextafter(j.time, INFINITY) - j.time));
    }
    out.tolerance = tol::pitch;
    if (options.prove) out.proof = prove_pitches(s, out.intervals, ex);
    return out;
}

}  // namespace dragon
