// The answers of the contest's questions as JSON (collide, min-pitch, turnaround, max-speed), built
// in one place: the dragon tool prints them for --json, its sweeps write them into their rows,
// and Python's to_dict() reads them, so all three hold the same answer for one scenario. And the
// sentences the library says about its answers.
#pragma once

#include <optional>

#include <string>

#include "dragon/analyses.hpp"
#include "dragon/contest.hpp"
#include "dragon/json.hpp"
#include "dragon/turnaround.hpp"

namespace dragon {

// One sentence: the grid, how each change is narrowed and what each run proves, and what a
// window narrower than the grid means.
std::string min_pitch_guarantee(const MinPitch& m);
// One paragraph: can the turning curve be shorter, and which of the studied turns this dragon
// can follow at all.
std::string turnaround_conclusion(const TurnaroundStudy& st);

// The overlap as an answer's "overlap_at_start" key: {"benches", "depth"}, or null.
Json overlap_json(const std::optional<Overlap>& o);

// The end of the valid motion as an answer's "jam" key: {"time", "travel", "handle", "kind",
// "ahead", "point", "tolerance", "enclosure", "proof"}, or null. "kind" is what happens as time
// runs forward; "ahead": the motion is valid until the jam (else from it). "enclosure":
// {"travel": [lo, hi], "time": [lo, hi]}, the motion proved continuous from t = 0 up to the end
// nearer it and past the jam at the other; "proof": {"method" (Jam::method), "steps",
// "unproved_steps"}.
Json jam_json(const std::optional<Jam>& j);
// The window an answer searched, both ways: "from", "to" (s) and "from_travel", "to_travel" (m of
// head travel), added to `answer`.
void add_window(Json& answer, const Searched& w);

// A first contact: {"time", "travel", "benches", "head_radius", "point", "tolerance"}.
Json contact_json(const Contact& c);
// What a first-contact search proved: {"method", "steps", "subdivisions", "unproved_steps",
// "unproved_travel", "least_separation", "covered_travel": [from, to]: the head
// travel the accepted steps cover, proved contact-free where "method" is "enclosure", "motion":
// the valid motion's proof over that range when the steps were proved, {"method" ("proved" or
// "proved+rate"), "steps", "unproved_steps", "unproved_travel"}, else null}.
Json proof_json(const ContactProof& p);
// collide's answer: the contact's keys (null where there is none), "evaluations", "enclosure"
// ({"travel": [lo, hi], "time": [lo, hi]}: the first contact lies within; null without one),
// "proof" (proof_json), the window searched both ways ("from", "to", "from_travel",
// "to_travel"), "jam", then "handles" (every handle then, or null) if asked for.
Json collide_answer(const CollideAnswer& a, bool with_handles);
// {"pitch", "below_range", "above_range", "turn_radius", "search", "grid", "intervals", "jam",
// "guarantee"}; the jam, if any, has the pitch it was met at.
Json min_pitch_answer(const MinPitch& m, double turn_radius);
// What min_pitch proved: {"method" ("enclosure cells", "enclosure cells, incomplete", or "runs"
// when not asked to prove), "proved": [[lo, hi], ...] (m, every pitch inside feasible),
// "unproved": the feasible intervals' parts left to the runs (null when not asked),
// "proved_colliding": [[lo, hi], ...] (m, every pitch inside meets a contact before the
// boundary), "unproved_colliding": the infeasible intervals' parts left to the runs (null when
// not asked), "least_feasible": [lo, hi] (m: the least feasible pitch of the range lies in it,
// PitchProof::least_lo/hi; null when nothing is proved feasible), "cells", "pitch_ranges",
// "subdivisions", "least_separation" (m, or null)}.
Json pitch_proof_json(const std::optional<PitchProof>& p);
// The S-curve's design, whether this dragon can follow it, the first contact and the clearance
// up to it if the check was run ("first_contact": contact_json or null; "clearance": the
// smallest clearance before it, with the window searched), and the length study if given (the
// command's; a sweep leaves it out). "jam": where the valid motion ends on the check's window,
// else on the design.
Json turnaround_answer(const SCurve& design, const std::optional<Jam>& design_jam,
                       const std::optional<RunClearance>& clearance, const TurnaroundStudy* study);
// {"max_head_speed", "ratio", "unbounded", "handle", "time", "travel", "tied", "head_arc", "limit",
// "from", "to", "from_travel", "to_travel", "jam", "scan_step", "scan_travel", "candidates",
// "evaluations"}.
Json max_speed_answer(const MaxSpeed& m, double limit);

// `dragon solve`'s summary.json: a key per question answered ("q1".."q5"): Q1's and Q4's tables
// (their files, times, rows and the rows left out, the window both ways, the jam that cut it,
// the first contact they run past), Q2 as collide's answer, Q3 as min-pitch's (and why its
// range moved), Q4's S-curve and whether this dragon can follow it, Q5 as max-speed's.
Json contest_summary(const ContestAnswers& a, const ContestOptions& options);

}  // namespace dragon
