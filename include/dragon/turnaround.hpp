// The turnaround (Q4, Q5): the coil-in spiral, an S-curve of two tangent circular arcs inside the
// turning space, and the coil-out spiral (the coil-in spiral turned by pi), as one Path; the
// S-curve's exact design, the study of its length, and the largest head speed under a limit.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dragon/executor.hpp"
#include "dragon/geometry.hpp"
#include "dragon/path.hpp"
#include "dragon/progress.hpp"
#include "dragon/scenario.hpp"
#include "dragon/valid_motion.hpp"
#include "dragon/window.hpp"
#include "dragon/analyses.hpp"

namespace dragon {

// The S-curve from the entry point A on the coil-in spiral to the exit point B = -A on the
// coil-out spiral. Arc 1 (centre c1, radius r1) leaves A tangent to the coil-in spiral turning
// clockwise; arc 2 (c2, r2) turns counter-clockwise and reaches B tangent to the coil-out spiral;
// the arcs touch at `joint`, |c1 - c2| = r1 + r2, and r1 = ratio * r2.
struct SCurve {
    double pitch = 0;         // of both spirals, m
    double entry_radius = 0;  // |A|, m
    double entry_theta = 0;   // polar angle of A on the coil-in spiral r = b theta (and of B on the coil-out one)
    double ratio = 0;         // r1 / r2
    Vec2 entry = Vec2::Zero();  // A
    Vec2 exit = Vec2::Zero();  // B = -A
    Vec2 direction = Vec2::Zero();  // unit direction of travel at A; the same at B (the spirals are point-symmetric)
    Vec2 c1 = Vec2::Zero();   // arc 1's centre, m
    Vec2 c2 = Vec2::Zero();   // arc 2's centre, m
    double r1 = 0;            // arc 1's radius, m
    double r2 = 0;            // arc 2's radius, m
    double angle1 = 0;        // clockwise angle arc 1 sweeps, rad
    double angle2 = 0;        // counter-clockwise angle arc 2 sweeps, rad
    Vec2 joint = Vec2::Zero();  // where arc 1 meets arc 2
    double length1 = 0;       // arc 1's length, m
    double length2 = 0;       // arc 2's length, m
    double length = 0;        // the S-curve's length, length1 + length2, m
    double max_radius = 0;    // farthest point of the S-curve from the centre, m
};

// Solves the S-curve exactly. Throws InputError for a non-positive pitch, radius or ratio.
SCurve design_s_curve(double pitch, double entry_radius, double ratio);
// The S-curve of a scenario: turn_pitch, turn_radius and arc_ratio.
SCurve design_s_curve(const Scenario& s);

// The composite path. Pieces: 0 coil-in spiral (u = theta, decreasing along the travel),
// 1 arc 1 (u = angle of the point about c1, decreasing), 2 arc 2 (u = angle about c2,
// increasing), 3 coil-out spiral (u = theta of the point -b theta (cos theta, sin theta),
// increasing). Arc position s = 0 at A (where the turn begins), so s < 0 on the coil-in spiral
// and s > length on the coil-out one; the path is unbounded both ways.
class TurnaroundPath final : public Path {
public:
    explicit TurnaroundPath(const SCurve& design);  // design_s_curve's: not checked again

    const SCurve& design() const { return design_; }  // the S-curve it turns on
    // Arc positions where pieces 1, 2 and 3 begin: 0, length1, length.
    double join_arc(int piece) const;
    // The range of u on a piece, as {u at the piece's start, u at its end} in the travel order.
    std::pair<double, double> piece_range(int piece) const;

    Located at(Place p) const override;
    double arc(Place p) const override;
    Located at_arc(double s) const override;
    double s_min() const override;
    double s_max() const override;
    double curvature(Place p) const override;
    double turning(Place rear, Place front) const override;
    double curvature_bounded_before(double k) const override;
    double curvature_bounded_after(double k) const override;
    int piece_count() const override { return 4; }
    double piece_begin(int piece) const override { return join_arc(piece); }
    std::pair<double, double> piece_span(int piece) const override { return piece_range(piece); }
    std::pair<double, double> curvature_span(int piece) const override;
    std::optional<Located> behind(const Located& from, double chord) const override;
    const Spiral* coil_in_spiral(Place p) const override { return p.piece == 0 ? &coil_in_ : nullptr; }

private:
    std::optional<Located> behind_on_arc(int piece, const Located& from, double chord) const;
    std::optional<Located> behind_on_coil_in(const Located& from, double chord) const;
    std::optional<Located> behind_on_coil_out(const Located& from, double chord) const;

    SCurve design_;
    Spiral coil_in_;
    double length_at_entry_;  // spiral length from the centre to A (and to B)
    double u1_start_, u1_end_, u2_start_, u2_end_;
};

// Q4: can the turning curve be shorter? One row per S-curve studied.
struct TurnStudyRow {
    double ratio;           // r1 / r2
    double entry_radius;    // where the turn starts, m (the turning space's radius by default)
    double r1;              // arc 1's radius, m
    double r2;              // arc 2's radius, m
    double angle;           // each arc's angle, rad (the S-curve's two arcs sweep the same angle)
    double s_curve_length;  // m
    // The head's whole way inside the turning space: coil-in spiral from the turning-space
    // boundary to the entry, the S-curve, and the coil-out spiral back out to the boundary, m.
    double inside_length;
    double max_radius;      // m; at most the turning-space radius for a turn that fits inside
    // Can the dragon follow this S-curve the whole way through, from far out on the coil-in
    // spiral to far out on the coil-out one? If not, where its valid motion ends (times with
    // t = 0 where the head enters the S-curve). Filled by study_turnaround / followability.
    std::optional<Jam> jam;
    bool followable() const { return !jam; }  // the dragon follows it the whole way
};
// Length against the radius ratio, entry at the turning-space boundary.
std::vector<TurnStudyRow> length_vs_ratio(double pitch, double turn_radius,
                                          const std::vector<double>& ratios);
// Length against the entry radius (<= turn_radius: the turn starts deeper inside), fixed ratio.
std::vector<TurnStudyRow> length_vs_entry_radius(double pitch, double turn_radius, double ratio,
                                                 const std::vector<double>& entry_radii);

// Fills each row's jam for this dragon: the S-curve of that row (pitch, its entry radius and
// ratio) searched the whole way through (find_jam).
void followability(std::vector<TurnStudyRow>& rows, double pitch, const BenchSpec& bench, double head_speed);

// Can this dragon follow the scenario's own S-curve (sim on the turnaround path) all the way
// through? Where its valid motion ends if not: the jam behind t = 0 first (the dragon cannot
// reach the turn as simulated), else the one ahead. The same jam every command reports.
std::optional<Jam> turnaround_jam(const Simulation& sim);

// Q4's study: the scenario's S-curve, and how the turn's length varies with the arcs' ratio and
// with where the turn starts.
struct TurnaroundStudy {
    SCurve design;                  // the scenario's own S-curve
    std::optional<Jam> design_jam;  // turnaround_jam: where the valid motion ends on the scenario's own S-curve
    std::vector<TurnStudyRow> by_ratio;  // over the ratio, the turn starting at the boundary
    std::vector<TurnStudyRow> by_entry;  // over the entry radius, at the scenario's ratio
    double ratio_spread;    // largest minus smallest S-curve length over by_ratio, m
};
// The default study: ratios 0.25..10 and entry radii from the boundary in to half of it, each
// row with whether this dragon can follow it.
TurnaroundStudy study_turnaround(const Scenario& s);
// The study as CSV text (header study,ratio,entry_radius,r1,r2,angle,s_curve_length,
// inside_length,max_radius,followable,jam_time,jam_handle,jam_kind; one line per row).
// write_study_csv (dragon/turnaround_csv.hpp, the io component) writes it to a file.
std::string study_csv(const TurnaroundStudy& study);

// What the proof of a run's least clearance established (min_clearance with `prove`).
struct ClearanceProof {
    bool proved = false;  // no two non-adjacent benches come within `lower` anywhere in the window
    double lower = 0.0;   // m: the bound proved, a little under the smallest clearance found
    int steps = 0;        // steps of head travel proved
    int subdivisions = 0; // steps not proved, taken again shorter
};

// Is the turnaround collision-free, and how close do benches come before they touch? The first
// contact over a window of the run (as collide finds it over the same window), and the smallest
// clearance between non-adjacent benches up to it, or over the whole window when there is none
// (past a contact the benches overlap, and a "clearance" there means nothing). Searched in head
// travel: the same at any head speed, with times scaled by 1 / speed.
struct RunClearance {
    // Smallest clearance, m: 0 at the first contact when there is one. When no two benches come
    // within the scan's cutoff (0.5 m), the cutoff, with bench_a = bench_b = 0.
    double distance = 0.0;
    double time = 0.0;         // when, s
    double travel = 0.0;       // the head's travel then, m
    int bench_a = 0;           // the closest pair's first bench then (1..N); 0 when none came within the cutoff
    int bench_b = 0;           // and its second, bench_a < bench_b
    std::optional<Contact> first_contact;  // the window's first contact, if any
    bool collision_free() const { return !first_contact; }  // no contact in the window
    ContactProof proof{};      // what the first-contact search proved over the window (`prove`)
    // With `prove` and no contact: the smallest clearance's lower bound, proved over the window.
    std::optional<ClearanceProof> clearance_proof;
    double scan_step = 0.0;    // s
    double scan_travel = 0.0;  // m of head travel: the scan's spacing (each local minimum then refined)
    int evaluations = 0;       // frames whose clearance the scan and its refinement computed
    Searched window;           // the window cut to the valid motion
    std::optional<Jam> jam;    // where the end of the valid motion cut it
};
// Over `window` cut to the valid motion (cut_window). `progress` hears of the scan's samples
// (most of the time taken). The first-contact search runs on `executor` (null:
// the calling thread alone), and proves every step it takes when `prove` is set
// (ContactSearchOptions::prove_steps; RunClearance::proof says what it proved). Throws InputError as cut_window does, ("clearance time range") for a
// window too long to scan (over 1e8 bench checks), and Cancelled when `executor` asks to stop.
RunClearance min_clearance(const Scenario& s, const RunWindow& window = kTurnaroundWindow,
                           const WorkProgress& progress = {}, Executor* executor = nullptr, bool prove = false);

// What Q5's proof established (docs/methods.md, section 10.1): branch and bound over head
// travel, each stretch of the window bounded from the chain at its two ends (a slope bound from
// interval arithmetic on the rigid-link relation), stretches split until every bound is within
// `tolerance` of the largest ratio found.
struct MaxSpeedProof {
    bool proved = false;    // every stretch of the window bounded: ratio_hi holds everywhere in it
    double ratio_lo = 0.0;  // the largest ratio found at a point, less its rounding error: the maximum is at least this
    double ratio_hi = 0.0;  // no handle's ratio exceeds this anywhere in the window (+inf when not proved)
    double max_head_speed_lo = 0.0;  // limit / ratio_hi, m/s (0 when not proved): every head speed up to it keeps to the limit
    double max_head_speed_hi = 0.0;  // limit / ratio_lo, m/s: any faster and some handle breaks it
    double tolerance = 0.0;  // relative: stretches are split until their bound is within this of the best found
    int stretches = 0;      // stretches bounded (the branch and bound's leaves)
    int subdivisions = 0;   // stretches split in two
    int evaluations = 0;    // chains the proof solved beyond the scan's
    int unproved = 0;       // stretches left unbounded: a handle moving back at one of its ends (the method needs
                            // every handle moving forward), or split down to 1e-11 m, or past the work cap
    double unproved_travel = 0.0;  // m of head travel those stretches cover
    double narrowest = 0.0;  // m of head travel: the narrowest stretch bounded
    // The valid motion over the window, which the bounds assume: proved by the walk asked to
    // prove every step (find_jam's JamSearchOptions::prove; docs/methods.md, section 4.1).
    JamSearchStats motion{};
    // "lipschitz bound" when every stretch was bounded (ratio_hi holds over the whole window),
    // else "lipschitz bound, incomplete" (ratio_hi is +inf: only the lower end is claimed).
    const char* method() const { return unproved == 0 ? "lipschitz bound" : "lipschitz bound, incomplete"; }
};

// How max_head_speed searches: the coarse scan's density, and whether to prove the maximum.
struct MaxSpeedOptions {
    // Bound the maximum over the whole window (MaxSpeed::proof; dragon max-speed --prove). Opt-in
    // as the first contact's proof is: it costs a few times the search's CPU (docs/performance.md;
    // its bounds run on the executor's workers with the scan).
    bool prove = false;
    double samples_per_link = 32.0;  // coarse scan samples per shortest link length (tests make it coarse)
};

// Q5: the largest head speed with every handle at or under `limit`. The speed ratio
// (largest handle speed over the head's) does not depend on the head speed, so it is maximised
// over the head's arc position once; the answer is limit / ratio.
struct MaxSpeed {
    double max_head_speed;  // 0 when `unbounded`
    double ratio;       // largest handle speed (its magnitude) / head speed over the range; +inf when unbounded
    int handle;         // the handle reaching it (0..N); the first of `tied` when several do
    std::vector<int> tied;  // every handle within 1e-12 (relative) of the largest speed then
                            // (handles on one arc move at the same speed)
    double time;        // when, on the scenario's own timeline (head at head_speed, t = 0 at the turn), s
    double travel;      // the head's travel from t = 0 then, m
    double head_arc;    // head's arc position then, m
    double scan_step;   // coarse scan step in time, s
    double scan_travel; // the same as head travel, m
    int candidates;     // local maxima of the coarse scan refined
    int evaluations;    // chains solved
    // The window searched: the one asked for cut to the valid motion, and the jam that cut it,
    // if one did. When the valid motion's own handle races there (speed_unbounded_at), its
    // speed grows without bound as the jam nears: no head speed keeps every handle under any limit.
    Searched window;
    std::optional<Jam> jam;   // the jam that cut the window, if one did
    bool unbounded = false;   // the handle racing at the jam: no head speed keeps to the limit
    // The proof (when asked for, and not unbounded): `ratio` lies in [ratio_lo, ratio_hi] and
    // max_head_speed in [max_head_speed_lo, max_head_speed_hi]. Points the proof evaluated count
    // as found: `ratio` is the largest ratio the scan, its refinement or the proof saw.
    std::optional<MaxSpeedProof> proof;
};
// Searches `window` of the turnaround run (the scenario's kind is taken as turnaround), in head
// travel: everything but the times is the same at any head speed. Speeds are signed along the
// path; the limit applies to their magnitude. Throws InputError for a limit that is not a finite
// speed > 0, as cut_window does, and ("time range") for a window too long to scan. Its scan (and,
// with the proof, each stretch's bound) runs on `executor`'s workers, on the calling thread
// without one; the answer is the same either way. Throws Cancelled when `executor` asks to stop.
MaxSpeed max_head_speed(const Scenario& s, double limit, const RunWindow& window = kTurnaroundWindow,
                        Executor* executor = nullptr, const MaxSpeedOptions& options = {});

// The largest handle speed (magnitude) over the head speed at one head arc position, and which handle.
struct SpeedRatio {
    double ratio;  // the largest |handle speed| / head speed
    int handle;    // which handle (0..N); the first when several tie
};
// The ratio with the head front handle at arc position head_arc, m, on `path`. Throws InputError
// as solve_chain does when the chain runs off the path.
SpeedRatio speed_ratio_at(const Path& path, const BenchSpec& spec, double head_arc);

}  // namespace dragon
