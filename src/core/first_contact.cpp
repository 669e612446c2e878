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
#include <array>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <cstdint>
#include <cmath>
#include <limits>
#include <vector>

#include "core/corner_gaps.hpp"
#include "core/motion.hpp"
#include "core/sat.hpp"
#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"

namespace dragon {

namespace {

constexpr double kSafety = 2.0;    // slack on the closing-speed bound over one step
constexpr double kMargin = 0.7;    // broad-phase margin, m
constexpr double kMaxTravel = 2.0; // m of head travel per step; keeps the bound's drift small
constexpr double kProbeGap = 2e-3; // m; below this clearance, try to bracket the contact

// Pairs beyond the broad phase's margin, bounded group by group. A bench's velocity field seen
// in a frame turning about the origin at rate w is v_c - w perp(c) + (omega - w) perp(x - c), so
// its points move there at most S(w) = |v_c - w perp(c)| + |omega - w| R (R: half-diagonal).
// The distance between two points does not depend on the frame, so it shrinks no faster than
// S_a(w) + S_b(w) for any one w. Benches are grouped in runs along the chain; each group has a
// rate w_G (its members' mean angular speed about the origin), V_G = max S_k(w_G), and
// rho_G = max |c_k| + R_k, which give S_k(w) <= V_G + |w - w_G| rho_G for its members. For two
// groups, the best w between w_G and w_H bounds every member pair's closing speed by
//     W_GH = V_G + V_H + |w_G - w_H| min(rho_G, rho_H),
// and each such pair not among the broad phase's candidates is more than the margin apart, and
// at least as far apart as the groups' bounding circles. Neighbouring turns turn at nearly the
// same rate, so W is far below twice the largest point speed in any single frame.
//
// That bound is weak for groups on different turns: they slide past each other at |w_G - w_H|
// times the radius, without closing. A second bound sees this. Any point x of bench k moves at
// (v_c - omega perp(c)) + omega perp(x), and perp(x) is square to x, so |x| changes at most at
// u_k = |v_c - omega perp(c)| (small: the chain turns about the origin almost rigidly). If a
// group's radii lie in [lo_G, hi_G] and another's in [lo_H, hi_H] with lo_H > hi_G, every member
// pair is at least lo_H - hi_G apart (|x - y| >= |y| - |x|), a gap that shrinks no faster than
// U_G + U_H (U: the largest u_k). A group pair may take the better of the two steps.
constexpr int kGroup = 8;  // benches per group

void radial_extents(const Frame& f, const std::vector<BenchMotion>& motion, std::vector<Radial>& out) {
    out.resize(f.benches.size());
    for (size_t k = 0; k < f.benches.size(); ++k) out[k] = radial_extent(f.benches[k], motion[k]);
}

// A lower bound on the distance between two benches, or two groups, from their radii alone
// (not positive when their radii overlap), and the time that distance lasts at least.
double radial_gap(const Radial& a, const Radial& b) { return std::max(b.lo - a.hi, a.lo - b.hi); }
double radial_step(const Radial& a, const Radial& b) {
    const double gap = radial_gap(a, b);
    if (!(gap > 0.0)) return 0.0;
    const double closing = a.speed + b.speed;
    return closing > 0.0 ? gap / (kSafety * closing) : INFINITY;
}

struct Group {
    Vec2 centre;
    double radius;  // bounding circle of the members' rectangles
    double rate;    // w_G
    double speed;   // V_G
    double reach;   // rho_G
    Radial radii;   // the members' radii all lie in [lo, hi] and change at most at U_G
};

double far_pairs_step(const Frame& f, const std::vector<BenchMotion>& motion, const std::vector<double>& half_diagonals,
                      const std::vector<Radial>& radial, double margin) {
    const size_t n = f.benches.size();
    std::vector<Group> groups;
    groups.reserve(n / kGroup + 1);
    for (size_t g0 = 0; g0 < n; g0 += kGroup) {
        const size_t g1 = std::min(n, g0 + kGroup);
        Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
        double rate = 0.0;
        int rated = 0;
        for (size_t k = g0; k < g1; ++k) {
            const Vec2 c = motion[k].centre;
            lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
            hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
            const double r2 = dot(c, c);
            if (r2 > 0.0) rate += cross(c, motion[k].v_centre) / r2, ++rated;
        }
        Group g{0.5 * (lo + hi), 0.0, rated ? rate / rated : 0.0, 0.0, 0.0, {INFINITY, 0.0, 0.0}};
        for (size_t k = g0; k < g1; ++k) {
            const BenchMotion& m = motion[k];
            const double diagonal = half_diagonals[k];
            g.radius = std::max(g.radius, norm(m.centre - g.centre) + diagonal);
            g.speed = std::max(g.speed, norm(m.v_centre - g.rate * perp(m.centre)) + std::abs(m.omega - g.rate) * diagonal);
            g.reach = std::max(g.reach, norm(m.centre) + diagonal);
            g.radii = {std::min(g.radii.lo, radial[k].lo), std::max(g.radii.hi, radial[k].hi),
                       std::max(g.radii.speed, radial[k].speed)};
        }
        groups.push_back(g);
    }
    double step = INFINITY;
    for (size_t a = 0; a < groups.size(); ++a) {
        const Group& ga = groups[a];
        for (size_t b = a; b < groups.size(); ++b) {
            const Group& gb = groups[b];
            const double closing = ga.speed + gb.speed + std::abs(ga.rate - gb.rate) * std::min(ga.reach, gb.reach);
            const double apart = std::max(margin, norm(ga.centre - gb.centre) - ga.radius - gb.radius);
            const double pair_step = closing > 0.0 ? apart / (kSafety * closing) : INFINITY;
            step = std::min(step, std::max(pair_step, radial_step(ga.radii, gb.radii)));
        }
    }
    return step;
}

// What the stepper remembers of the near pairs at the last evaluation: the corner-gap rates and
// the curvature bound the step relied on, to check that bound against the rates found next.
struct PairMemory {
    double time;
    std::array<double, 8> rates;
    double curvature;
};
std::uint64_t key_of(int a, int b) { return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b); }

// The near pairs' memories by pair: a flat open-addressing table (a few hundred entries written
// and read per evaluation; a node-based map spent more time allocating than the bounds took).
class Memory {
public:
    const PairMemory* find(std::uint64_t key) const {
        if (slots_.empty()) return nullptr;
        for (size_t k = hash(key);; k = (k + 1) & mask()) {
            if (slots_[k].key == key) return &slots_[k].value;
            if (slots_[k].key == kEmpty) return nullptr;
        }
    }
    void emplace(std::uint64_t key, const PairMemory& value) {
        if (2 * (size_ + 1) > slots_.size()) grow();
        size_t k = hash(key);
        while (slots_[k].key != kEmpty && slots_[k].key != key) k = (k + 1) & mask();
        if (slots_[k].key == kEmpty) ++size_;
        slots_[k] = {key, value};
    }
    void clear() {
        for (Slot& s : slots_) s.key = kEmpty;
        size_ = 0;
    }
    void swap(Memory& other) noexcept {
        slots_.swap(other.slots_);
        std::swap(size_, other.size_);
    }
    template <class F>
    void for_each(F&& f) {
        for (Slot& s : slots_)
            if (s.key != kEmpty) f(s.value);
    }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    struct Slot {
        std::uint64_t key = kEmpty;
        PairMemory value{};
    };
    size_t mask() const { return slots_.size() - 1; }
    size_t hash(std::uint64_t key) const { return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & mask(); }
    void grow() {
        std::vector<Slot> old(std::max<size_t>(64, 2 * slots_.size()));
        old.swap(slots_);
        size_ = 0;
        for (const Slot& s : old)
            if (s.key != kEmpty) emplace(s.key, s.value);
    }
    std::vector<Slot> slots_;
    size_t size_ = 0;
};

struct Approach {
    // The closest pair among those looked at: exact whenever the true clearance is below
    // kProbeGap (the pairs passed over are farther apart than that), else only an upper bound.
    Clearance clear;
    double safe_step;  // s: no contact can happen sooner
    double rate;       // d/dt of the closest pair's separation now (negative: closing)
    bool bound_broken; // a near pair's rates changed faster than the last step assumed
    // s: no pair but the closest one can touch sooner. A bracket for the closest pair's contact
    // must end by then, or the bisection in it could pass over another pair's brief contact.
    double others_step;
};

// One pass over the broad phase's pairs gives the clearance and the safe step.
//
// Each pair first gets the first-order step g / (kSafety L) from its projected gap g and the
// bound L on its closing speed. Pairs whose first-order step could decide the step are then
// looked at closer: their eight corner gaps, each with its exact rate, are bounded to second
// order, d(t + h) >= d + rate h - M h^2 / 2, with M kSafety times the larger of the rate
// changes seen since the last evaluation and a rotational floor. A pair's step is the better
// of the two bounds. This is what makes grazing passes cheap: a corner gliding past at a
// tiny distance with zero rate still allows sqrt(2 d / M), where the first-order bound would
// crawl. The curvature each step relied on is checked at the next evaluation; if the rates
// changed faster, the caller retreats and retries shorter.
// `memory` is what the last accepted evaluation saw; this one's goes to `next` (cleared first),
// for the caller to keep if it accepts the step.
Approach approach(const Frame& f, double t, double max_step, const Memory& memory, Memory& next, bool check) {
    Approach a{{INFINITY, 0, 0, {}, {}}, INFINITY, 0.0, false, INFINITY};
    if (f.benches.size() < 3) return a;
    const std::vector<BenchMotion> motion = bench_motions(f);
    // Scratch kept per thread (a search evaluates hundreds of frames).
    thread_local std::vector<double> gaps, half_diagonals;
    thread_local std::vector<Radial> radial;
    half_diagonals.resize(f.benches.size());
    for (size_t k = 0; k < f.benches.size(); ++k) half_diagonals[k] = half_diagonal(f.benches[k]);
    radial_extents(f, motion, radial);
    // Pairs beyond the margin: bounded group by group (far_pairs_step).
    const double cap = std::min(max_step, far_pairs_step(f, motion, half_diagonals, radial, kMargin));
    const auto pairs = candidate_pairs(f, kMargin);
    struct Candidate {
        double first_order;
        double bound;
        size_t k;
    };
    thread_local std::vector<Candidate> tight;
    tight.clear();
    gaps.resize(pairs.size());
    double best_gap = INFINITY;
    size_t seed = 0;
    for (size_t k = 0; k < pairs.size(); ++k) {
        const size_t i = static_cast<size_t>(pairs[k].first - 1), j = static_cast<size_t>(pairs[k].second - 1);
        // Benches on neighbouring turns slide past each other: when their radii alone keep them
        // apart for the whole step and farther than a probe would look, they cannot set the step,
        // touch, or be probed, and need no closer look (most pairs, away from the centre).
        const double radial_first_order = radial_step(radial[i], radial[j]);
        if (radial_first_order >= cap && radial_gap(radial[i], radial[j]) >= kProbeGap) {
            gaps[k] = INFINITY;
            continue;
        }
        const Rect& ra = f.benches[i];
        const double g = sat_gap(ra, f.benches[j]).gap;  // a lower bound on the distance
        gaps[k] = g;
        if (g < best_gap) { best_gap = g; seed = k; }
        // Relative velocity field of b seen from a: affine, so within a's rectangle its norm is
        // at most its value at a's centre plus the turn-rate difference times the half-diagonal.
        const BenchMotion& ma = motion[i];
        const BenchMotion& mb = motion[j];
        const double gap = std::max(g, 0.0);
        const double bound = norm(mb.at(ma.centre) - ma.v_centre) + std::abs(mb.omega - ma.omega) * half_diagonals[i] +
                             std::abs(mb.omega) * gap;
        // First-order step gap / (kSafety bound), divided out only for the pairs that could set it.
        if (gap < cap * kSafety * bound) {
            const double first_order = std::max(gap / (kSafety * bound), radial_first_order);
            if (first_order < cap) tight.push_back({first_order, bound, k});
        }
    }
    // Smallest first-order step first, popped from a heap: usually only a part of the list is
    // looked at before the first-order steps exceed the step found so far.
    const auto later = [](const Candidate& x, const Candidate& y) { return x.first_order > y.first_order; };
    std::make_heap(tight.begin(), tight.end(), later);
    next.clear();
    double step = cap;
    // Each pair looked at and the step it allows; every other allows at least `skipped`.
    thread_local std::vector<std::pair<std::uint64_t, double>> pair_steps;
    pair_steps.clear();
    double skipped = cap;
    while (!tight.empty()) {
        std::pop_heap(tight.begin(), tight.end(), later);
        const Candidate c = tight.back();
        tight.pop_back();
        if (c.first_order >= step) {  // this pair and the rest cannot lower the step
            skipped = std::min(skipped, c.first_order);
            break;
        }
        const int ia = pairs[c.k].first - 1, ib = pairs[c.k].second - 1;
        const BenchMotion& ma = motion[static_cast<size_t>(ia)];
        const BenchMotion& mb = motion[static_cast<size_t>(ib)];
        const auto gaps8 = corner_gaps(f.benches[static_cast<size_t>(ia)], ma, f.benches[static_cast<size_t>(ib)], mb);
        // Rotational floor: the corner-to-edge direction turns at most at |omega_a| + |omega_b|,
        // tilting a relative velocity of size <= bound.
        double observed = (std::abs(ma.omega) + std::abs(mb.omega)) * c.bound;
        const std::uint64_t key = key_of(ia, ib);
        PairMemory mem{t, {}, 0.0};
        if (const PairMemory* last = memory.find(key); last && last->time != t) {
            const double dt = std::abs(t - last->time);
            for (size_t q = 0; q < 8; ++q) {
                const double change = std::abs(gaps8[q].rate - last->rates[q]);
                observed = std::max(observed, change / dt);
                // The last step assumed the rates change by at most curvature * dt.
                if (check && change > last->curvature * dt * (1.0 + 1e-9) + 1e-12) a.bound_broken = true;
            }
        }
        mem.curvature = kSafety * observed;
        double h2 = INFINITY;
        for (size_t q = 0; q < 8; ++q) {
            mem.rates[q] = gaps8[q].rate;
            h2 = std::min(h2, second_order_step(gaps8[q].distance, gaps8[q].rate, mem.curvature));
        }
        next.emplace(key, mem);
        const double pair_step = std::max(c.first_order, h2);
        pair_steps.push_back({key, pair_step});
        step = std::min(step, pair_step);
    }
    a.safe_step = step;
    if (pairs.empty()) {
        a.clear = clearance(f, kMargin);
        a.others_step = step;
        return a;
    }
    // Exact distances only where the projected gap (a lower bound) could still win.
    auto exact = [&](size_t k) {
        const Separation s = separation(f.benches[static_cast<size_t>(pairs[k].first - 1)],
                                        f.benches[static_cast<size_t>(pairs[k].second - 1)]);
        if (s.distance < a.clear.distance) a.clear = {s.distance, pairs[k].first, pairs[k].second, s.axis, s.point};
    };
    if (gaps[seed] < INFINITY) exact(seed);
    for (size_t k = 0; k < pairs.size(); ++k)
        if (k != seed && gaps[k] < a.clear.distance) exact(k);
    const std::uint64_t closest = a.clear.bench_a > 0 ? key_of(std::min(a.clear.bench_a, a.clear.bench_b) - 1,
                                                                std::max(a.clear.bench_a, a.clear.bench_b) - 1)
                                                       : ~std::uint64_t{0};
    a.others_step = skipped;
    for (const auto& [key, pair_step] : pair_steps)
        if (key != closest) a.others_step = std::min(a.others_step, pair_step);
    if (a.clear.bench_a > 0 && a.clear.distance > 0.0) {
        // Separation rate of the closest pair: the witness on b moving away from a along the axis.
        const BenchMotion& ma = motion[static_cast<size_t>(a.clear.bench_a - 1)];
        const BenchMotion& mb = motion[static_cast<size_t>(a.clear.bench_b - 1)];
        const Vec2 q = a.clear.point;
        const Vec2 p = q - a.clear.distance * a.clear.axis;
        a.rate = dot(a.clear.axis, mb.at(q) - ma.at(p));
    }
    return a;
}

double head_radius(const Frame& f) { return norm(f.handles.front().pos); }

Contact make_contact(const Simulation& sim, double t, int steps, double time_tol) {
    Frame f = sim.frame(t);
    const Clearance c = clearance(f, kMargin);
    const double rounding = 2.0 * (std::nextafter(t, INFINITY) - t);
    return {t, c.bench_a, c.bench_b, head_radius(f), c.point, std::move(f), steps, std::max(time_tol, rounding)};
}

// The search over one range. `stop()` is asked once per step: true abandons the search (a
// contact was found in an earlier range). `steps` counts the evaluations.
template <class Stop>
std::optional<Contact> search_range(const Simulation& sim, double t_from, double t_to, const StepObserver& on_step,
                                    const Stop& stop, int& steps) {
    // Everything scales with the head's speed: the chain at speed v is the chain at 1 m/s with
    // time divided by v. A step covers at most kMaxTravel of head travel, and the contact time
    // is found to tol::contact_time and to at most that many metres of head travel (so 1e-9 s at
    // the contest's 1 m/s, and proportionally finer for a faster dragon).
    const double speed = sim.scenario().head_speed;
    const double max_step = kMaxTravel / speed;
    const double time_tol = tol::contact_time * std::min(1.0, 1.0 / speed);
    Frame f;
    steps = 0;
    double t = t_from;
    Memory memory, seen;
    sim.frame_into(t, f);
    Approach a = approach(f, t, max_step, memory, seen, false);
    memory.swap(seen);
    ++steps;
    if (a.clear.distance <= 0.0) return make_contact(sim, t, steps, time_tol);
    double retry_cap = INFINITY;  // after a broken curvature bound, retry shorter from t

    while (t < t_to) {
        if (stop()) return std::nullopt;
        // A pair grazing within rounding of touching, closing too slowly to bound: contact now
        // (also when the step is below the resolution of t itself, late in a slow run).
        if (a.safe_step < time_tol || t + a.safe_step == t) return make_contact(sim, t, steps, time_tol);
        // Bracket: a Newton probe on the closest pair once it is nearly touching, no farther
        // than any other pair could touch (the bisection below sees only the clearance's sign,
        // and would pass over another pair's contact that opens and closes inside its bracket).
        double t_hi = std::numeric_limits<double>::quiet_NaN();
        if (a.clear.distance < kProbeGap && a.rate < 0.0) {
            const double probe = std::min({t_to, t + 1.5 * a.clear.distance / -a.rate, t + a.others_step});
            sim.frame_into(probe, f);
            ++steps;
            if (clearance(f, kMargin).distance <= 0.0) t_hi = probe;
        }
        if (std::isnan(t_hi)) {
            const double next = std::min({t + a.safe_step, t + retry_cap, t_to});
            if (next <= t) break;
            sim.frame_into(next, f);
            ++steps;
            const Approach b = approach(f, next, max_step, memory, seen, true);
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
            sim.frame_into(mid, f);
            ++steps;
            if (clearance(f, kMargin).distance > 0.0) lo = mid; else hi = mid;
        }
        return make_contact(sim, hi, steps, time_tol);
    }
    return std::nullopt;
}

}  // namespace

// The range is cut into chunks searched on all cores, earliest first. Each chunk's search is
// exact for its own range, and a chunk that starts with benches overlapping reports its start:
// the overlap began in an earlier chunk, which then reports that contact itself. So the first
// contact is the one of the earliest chunk reporting any; chunks after it are abandoned. Every
// chunk before it has run to its end, so the answer (and the evaluation count) does not depend
// on how the threads were scheduled.
std::optional<Contact> first_contact(const Simulation& sim, double t_from, double t_to,
                                     const ContactSearchOptions& options) {
    // Both ends within the valid motion (the range between them then is too); searched here,
    // once, so that the frames below find it known.
    sim.require_valid(t_from, "--from");
    sim.require_valid(t_to, "--to");
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const size_t threads = options.on_step ? 1 : options.threads > 0 ? static_cast<size_t>(options.threads) : cores;
    auto never = [] { return false; };
    if (threads == 1 || !(t_to > t_from)) {
        int steps = 0;
        return search_range(sim, t_from, t_to, options.on_step, never, steps);
    }
    const size_t chunks = 8 * threads;
    std::vector<double> edge(chunks + 1);
    for (size_t k = 0; k <= chunks; ++k)
        edge[k] = k == chunks ? t_to : t_from + (t_to - t_from) * static_cast<double>(k) / static_cast<double>(chunks);
    std::vector<std::optional<Contact>> found(chunks);
    std::vector<int> steps(chunks, 0);
    std::atomic<size_t> next{0}, winner{chunks};
    std::exception_ptr failure;
    std::mutex failure_lock;
    auto work = [&] {
        // Latest chunk first: the one holding the contact usually costs most (short steps, then
        // the bisection), so it starts early, and the ones after it start overlapping and end at
        // once. The answer is the same in any order.
        for (size_t taken; (taken = next++) < chunks;) {
            const size_t k = chunks - 1 - taken;
            if (winner.load() < k) continue;
            try {
                found[k] = search_range(sim, edge[k], edge[k + 1], {}, [&] { return winner.load(std::memory_order_relaxed) < k; },
                                        steps[k]);
            } catch (...) {
                const std::lock_guard<std::mutex> hold(failure_lock);
                if (!failure) failure = std::current_exception();
                winner = 0;  // stop everyone
            }
            if (found[k]) {
                size_t w = winner.load();
                while (k < w && !winner.compare_exchange_weak(w, k)) {
                }
            }
        }
    };
    std::vector<std::thread> pool;
    for (size_t w = 1; w < threads; ++w) pool.emplace_back(work);
    work();
    for (std::thread& th : pool) th.join();
    if (failure) std::rethrow_exception(failure);
    const size_t w = winner.load();
    if (w == chunks) return std::nullopt;
    Contact c = std::move(*found[w]);
    c.steps = 0;
    for (size_t k = 0; k <= w; ++k) c.steps += steps[k];
    return c;
}

}  // namespace dragon
