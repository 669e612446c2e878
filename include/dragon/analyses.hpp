// The contest's questions as library calls: the coiling-in table, first contact (Q2) and the
// minimum pitch (Q3). The turnaround questions (Q4, Q5) are in turnaround.hpp.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dragon/chain.hpp"
#include "dragon/collision.hpp"
#include "dragon/constants.hpp"
#include "dragon/executor.hpp"
#include "dragon/progress.hpp"
#include "dragon/valid_motion.hpp"
#include "dragon/window.hpp"

namespace dragon {

// Frames at t0, t0 + dt, ..., t1 (inclusive, by index so no float drift), computed on the
// executor's workers (null: the calling thread alone).
std::vector<Frame> simulate_table(const Simulation& sim, double t0, double t1, double dt, Executor* executor = nullptr);
// The same into `frames`, reusing its storage (a table of 301 frames is 7 MB: allocating and
// first touching it costs more than computing it).
void simulate_table_into(const Simulation& sim, double t0, double t1, double dt, std::vector<Frame>& frames,
                         Executor* executor = nullptr);

// The window an analysis of this path looks at by default: on the plain spiral from t = 0 as far
// as the dragon can follow it (an open end, +inf m), on the turnaround path kTurnaroundWindow.
RunWindow default_window(PathKind kind);

// A window cut to the valid motion: the head travel looked at, and where the end of the valid
// motion cut the window short.
struct WindowCut {
    double from = 0.0;          // m of head travel
    double to = 0.0;            // m of head travel
    std::optional<Jam> before;  // the jam that cut its start
    std::optional<Jam> after;   // the jam that cut its end
    // The same window in time too, at this head speed (m/s).
    Searched searched(double head_speed) const;
};
// Throws InputError ("time range start", "time range end": the end as given) for an end that is
// not a finite number (the end may be +inf: as far as the motion goes, where it ends), a start
// past the end of the valid motion or an end before its beginning, or a window holding no
// moment of it.
WindowCut cut_window(const Simulation& sim, const RunWindow& window);
// Throws PastTheValidMotion (or InputError, off the path) naming `at` as given ("120 m", "5")
// under `field` unless the moment is within the valid motion.
void require_valid_at(const Simulation& sim, const Along& at, Key field);

// Frames at the given times (in any order; each within the valid motion, else the InputError
// Simulation::frame throws, before any is made), on the executor's workers: `out(k, frame)`
// hears the frame of times[k] on the worker that made it, to copy what it needs where it
// belongs (a caller filling arrays copies each frame once).
void simulate_at(const Simulation& sim, const std::vector<double>& times,
                 const std::function<void(std::size_t, const Frame&)>& out, Executor* executor = nullptr);

// What a first-contact search proved (docs/methods.md, section 6): each step it accepted over
// [proved_from, proved_to] (m of head travel) was proved free of contact by enclosing every
// bench over the whole step (core/swept_proof.hpp), except `unproved_steps` steps covering
// `unproved_travel` m, which rest on the rate bound checked at their ends (tol::rate_safety):
// every step when the search was not asked to prove them (ContactSearchOptions::prove_steps),
// else those where a link turned too far over the step for the enclosures.
struct ContactProof {
    int proved_steps = 0;          // steps proved contact-free by enclosures
    int subdivisions = 0;          // steps whose proof failed, taken again shorter
    int unproved_steps = 0;        // steps accepted on the rate bound alone
    double unproved_travel = 0.0;  // m of head travel they cover
    double least_gap = INFINITY;   // m: the least separation the proved steps proved (at most 0.05 m)
    double proved_from = 0.0;      // m of head travel
    double proved_to = 0.0;        // m of head travel: no contact on [proved_from, proved_to]
    // "enclosure" (every step proved), "rate" (none: the search was not asked to prove them) or
    // "enclosure+rate" (some steps on the rate bound alone).
    const char* method() const {
        return unproved_steps == 0 ? "enclosure" : proved_steps == 0 ? "rate" : "enclosure+rate";
    }
    // The valid motion over the range, which the steps' proofs assume (docs/methods.md, section
    // 4.1): proved by the walk asked to prove every step (find_jam's JamSearchOptions::prove) when
    // the search was asked to prove its own, else nothing of it looked at here (`motion_checked`
    // false; the simulation's own walk proves what it does by default).
    bool motion_checked = false;
    JamSearchStats motion{};
};

// Q2: the first moment two non-adjacent benches touch. The search runs in head travel, so the
// contact (its benches, point, head radius, travel) is the same at any head speed and its time
// is travel / speed.
struct Contact {
    double time;                // s
    int bench_a;                // the touching pair's first bench, 1..N
    int bench_b;                // and its second, bench_a < bench_b
    double head_radius;         // m: the head front handle's distance from the origin then
    Vec2 point = Vec2::Zero();  // contact witness point
    Frame frame;    // the whole chain at that moment (speeds at the scenario's head speed)
    int steps = 0;  // clearance evaluations the search used
    // How closely `time` is known, s: tol::travel / head speed, coarser only where t's own
    // rounding is larger.
    double tolerance = 0.0;
    double travel = 0.0;            // m: the head's travel from t = 0 then
    double travel_tolerance = 0.0;  // m: how closely `travel` is known (tol::travel)
    // The first contact lies in [enclosure_lo, enclosure_hi], m of head travel: no contact
    // before enclosure_lo is proved (proof.proved_to), benches touch at enclosure_hi (= travel).
    double enclosure_lo = 0.0;
    double enclosure_hi = 0.0;
    double enclosure_time_lo = 0.0;  // s: the same at the scenario's head speed
    double enclosure_time_hi = 0.0;  // s
    ContactProof proof{};  // what the search proved over the range up to the contact
};
// The search takes the range in stretches of head travel cut at fixed places (multiples of
// 10 m), spread over the executor's workers: the answer, and the work it took, do not depend on
// the number of workers, nor on which one finished first.
// A contact-free stretch as times, s, on the simulation's own clock (the search steps in head
// travel and reports each step's ends as Simulation::time_of them).
using StepObserver = std::function<void(double from, double to)>;
// How first_contact searches: where it runs, and what it tells or skips.
struct ContactSearchOptions {
    // If given, hears of every interval [from, to] the search has declared contact-free by its
    // bounds (without looking inside), in order; the search then runs on the calling thread.
    StepObserver on_step;
    Executor* executor = nullptr;  // null: the calling thread alone
    // While the chain coils in along one spiral (the plain spiral; the turnaround before its
    // turn), leave out of each stretch's search the benches proved unable to touch
    // anything over it (their turn of the spiral stays clear of the next); false watches every
    // bench, for checking that proof.
    bool skip_untouched_tail = true;
    // If given, receives what the search proved over the range (also when nothing touched).
    ContactProof* proof = nullptr;
    // How many times the closing rates measured at a step's start the step's length allows for
    // (tol::rate_safety): it chooses the steps. Tests set it to 1 or below to show the proof
    // rejects the steps it makes too long.
    double rate_safety = tol::rate_safety;
    // Prove every accepted step by enclosures (core/swept_proof.hpp; `dragon collide --prove`).
    // Off by default: on the contest's Q2 it takes about twice the evaluations and 3 times the
    // CPU, beyond the speed targets; without it each step rests on the rate bounds checked at
    // its end (ContactProof::method() "rate").
    bool prove_steps = false;
    // Check each step's rate bounds at its end and retry it shorter when they broke (the
    // default). false only for tests: the rate assumption alone, to show what it misses.
    bool check_step_ends = true;
};
// Both ends must lie within the valid motion (Simulation::valid_range; throws InputError
// otherwise): clamp `t_to` to valid_range().to to search as far as the dragon can go.
std::optional<Contact> first_contact(const Simulation& sim, double t_from, double t_to,
                                     const ContactSearchOptions& options = {});
// The same over head travel [x_from, x_to], m (both within Simulation::valid_range's travel).
std::optional<Contact> first_contact_travel(const Simulation& sim, double x_from, double x_to,
                                            const ContactSearchOptions& options = {});

// Benches overlapping where a search starts (`start`, as asked): "benches 1 and 24 already
// overlap at 0 m of head travel, where the search starts (by 0.114626 m): their first contact is
// before it".
std::string overlap_sentence(const Overlap& o, const Along& start);

// Q2 as `dragon collide` asks it: the first contact over a window, cut to the valid motion.
struct CollideAnswer {
    std::optional<Contact> contact;  // none: nothing touched in the window searched
    RunWindow asked;   // the window as given
    Searched window;   // the stretch searched: the window cut to the valid motion
    // The end of the valid motion where it cut the window short and nothing touched before it.
    std::optional<Jam> jam;
    // The contact is at the window's start with the benches already overlapping there: they
    // first touched before it. `overlap` says which two, and how deep.
    bool overlapping = false;
    std::optional<Overlap> overlap;
    ContactProof proof{};  // what the search proved over the window searched
};
// Throws InputError as cut_window does. Benches already overlapping where the window starts are
// a verdict, not a refusal: the answer has `overlap` set (and the contact at the start), the
// same for every command, sweep and front end.
CollideAnswer collide(const Simulation& sim, const RunWindow& window, Executor* executor = nullptr);
// The same searched as `options` say (its executor, prove_steps, rate_safety; its `proof` is
// ignored: the answer's own is filled).
CollideAnswer collide(const Simulation& sim, const RunWindow& window, const ContactSearchOptions& options);
// The motion's first contact: collide over the path's default window (default_window). This is
// the one event every command reports as the first contact: collide and turnaround by default,
// the contest's Q2, a picture of the collision, a film's caption.
CollideAnswer first_contact_of_motion(const Simulation& sim, Executor* executor = nullptr);
// The same searched as `options` say (the contest's Q2 with its proof: ContestOptions::prove).
CollideAnswer first_contact_of_motion(const Simulation& sim, const ContactSearchOptions& options);
// For what a table, picture or film shows over [t_from, t_to] (s): the first contact over the
// path's default window widened to take that range in. Inside the default window it is the
// motion's first contact; a range reaching outside it gets the earliest contact of the two.
// Benches already overlapping where the search starts give a contact there, marked
// `overlapping`, rather than an error.
CollideAnswer first_contact_covering(const Simulation& sim, double t_from, double t_to, Executor* executor = nullptr);

// When the head front handle reaches the turning space's boundary coiling in: on the plain
// spiral the moment its radius is the scenario's turn_radius (before t = 0 if it starts inside),
// on the turnaround path t = 0 (the turn starts there). boundary_travel: the head's travel then, m.
double boundary_time(const Simulation& sim);
double boundary_travel(const Simulation& sim);

// Q3: smallest pitch for which the head reaches the turning-space boundary without a collision.
struct PitchInterval {
    double lo;      // m
    double hi;      // m
    bool feasible;  // whether the pitches inside reach the boundary untouched
};
// A pitch at which the dragon cannot follow the spiral to the boundary at all.
struct PitchJam {
    double pitch;  // m
    Jam jam;       // where the valid motion ended at that pitch
};
// What min_pitch proved (MinPitchOptions::prove; docs/methods.md, section 8.1), of every pitch
// of the range, not only the pitches run: every pitch in each `proved` range reaches the boundary
// with no two benches touching (by enclosures over cells of head radius and pitch), every pitch
// in each `proved_colliding` range meets a contact before it (one bench's corner inside another
// at one head radius for all of them). The `unproved` parts of the feasible intervals and the
// `unproved_colliding` parts of the others (within a few times tol::pitch of a change of
// feasibility, or where a link spans a quarter turn or more, or the runs end in a jam, or where
// pitches of the other kind lie between the grid's, or past 10 000 ranges of pitches in one of
// the proof's parts) rest on the runs.
struct PitchProof {
    std::vector<PitchInterval> proved;    // m: ranges of pitches proved feasible (feasible = true)
    std::vector<PitchInterval> unproved;  // m: parts of feasible intervals not proved
    std::vector<PitchInterval> proved_colliding;    // m: ranges of pitches proved infeasible (feasible = false)
    std::vector<PitchInterval> unproved_colliding;  // m: parts of infeasible intervals not proved
    int cells = 0;          // cells of head radius and pitch proved contact-free
    int pitch_ranges = 0;   // ranges of pitches marched, or proved colliding
    int subdivisions = 0;   // cells taken again smaller (a shorter radius step, or half the pitches)
    double least_gap = INFINITY;  // m: the least separation proved (at most 0.05 m)
    // m: the least feasible pitch of the range lies in [least_lo, least_hi]. Every pitch below
    // least_lo collides (the proved colliding ranges from the range's low end on; the low end
    // itself when none starts there). NaN when nothing is proved feasible.
    double least_lo = NAN;
    // m: the least pitch proved feasible (it reaches the boundary untouched); NaN when none is.
    double least_hi = NAN;
    // "enclosure cells" (every pitch of the range proved feasible or colliding), or
    // "enclosure cells, incomplete".
    const char* method() const {
        return unproved.empty() && unproved_colliding.empty() ? "enclosure cells" : "enclosure cells, incomplete";
    }
};

// Q3's answer: the smallest feasible pitch and the feasibility of the whole range searched.
struct MinPitch {
    // The smallest feasible pitch: where the first feasible interval begins, when that is a
    // change found inside the range. NaN when the range holds no such change: below_range (the
    // range's low end is already feasible, so the answer lies at or below it) or above_range
    // (no pitch in the range is feasible).
    double pitch;
    bool below_range = false;  // feasible already at the range's low end
    bool above_range = false;  // nothing in the range is feasible
    std::vector<PitchInterval> intervals;  // alternating feasible / infeasible over the range
    double search_lo;  // the range searched, m
    double search_hi;  // m
    // The search's range must start above this pitch: the bench width, or where the head
    // would start on the turning space's edge (turn_radius / start_turn; lowest_is_start),
    // whichever is larger. A below_range answer lies between it and search_lo.
    double lowest = 0.0;
    bool lowest_is_start = false;  // `lowest` is the start on the turning space's edge, not the width
    double grid;                           // the first scan's pitch spacing, m
    // The largest pitch probed at which the run cannot reach the boundary because the valid
    // motion ends first (it is infeasible for that reason, not for a collision); none if no
    // run was cut short.
    std::optional<PitchJam> jam;
    double tolerance;                      // each change of feasibility located to this, m
    std::optional<PitchProof> proof;       // what was proved (MinPitchOptions::prove), else none
};
// The run of the head to the boundary at one pitch: its first contact, else the end of the
// valid motion if that comes before the boundary. Feasible when neither happens.
struct BoundaryRun {
    std::optional<Contact> contact;  // the first contact before the boundary
    std::optional<Jam> jam;          // the end of the valid motion before the boundary (and before any contact)
    bool feasible() const { return !contact && !jam; }  // neither: the head reaches the boundary untouched
};
// `s` with its pitch set to `pitch` (m). Throws InputError when that pitch puts the head's start
// inside the turning space, and as Simulation does for a scenario it refuses.
BoundaryRun run_to_boundary(Scenario s, double pitch);
// The first contact of that run (none also when the run jams first).
std::optional<Contact> contact_before_boundary(Scenario s, double pitch);
// The first scan's pitch grid, m: feasibility windows narrower than this can slip between two
// grid points, so `grid` trades time for the narrowest window the scan is sure to see.
inline constexpr double kDefaultPitchGrid = 2.5e-3;
inline constexpr int kMaxPitchGridSteps = 100000;  // about 10 minutes of runs on 2 cores
// The first scan's runs over [lo, hi] on `grid` (a range that is a whole number of spacings up
// to rounding gets that number): what a search costs, most of its time.
double pitch_grid_steps(double lo, double hi, double grid);
// Runs beyond which a search is out of proportion to the contest's (80 on 0.35..0.55 m): a
// front end says so before it starts.
inline constexpr double kCostlyPitchGridSteps = 800;
// `progress` hears of the first scan's runs, one per grid pitch (most of the time taken).
struct MinPitchOptions {
    double grid = kDefaultPitchGrid;  // the first scan's pitch spacing, m
    WorkProgress progress;         // hears of the first scan's runs, one call per run
    Executor* executor = nullptr;  // runs the pitches in parallel; null: the calling thread alone
    // Prove every pitch of the range feasible or colliding as its interval says (MinPitch::proof;
    // dragon min-pitch --prove), not only the pitches run. Opt-in: it costs about as much again
    // as the search (the contest: 126 ms against 61 ms on one thread).
    bool prove = false;
};
// The answer and any error are the same whatever the executor and its size (the pitches run
// are fixed in advance; an error is the one of the smallest pitch that failed). Throws
// InputError for a range it cannot search: "pitch search range start" (lo puts the head's start
// inside the turning space), "pitch search range end", "pitch grid", or lo, hi and the width
// out of order.
MinPitch min_pitch(const Scenario& s, double lo, double hi, const MinPitchOptions& options = {});

}  // namespace dragon
