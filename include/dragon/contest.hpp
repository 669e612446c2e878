// The contest's five questions on one scenario, as `dragon solve` answers them: which windows,
// ranges and limits each question uses, what runs in parallel, and where the end of the valid
// motion or a first contact cuts a question short. The answers are data; an application writes
// the workbooks (dragon/tables.hpp) and words them.
//
// Every window is head travel (the contest's "0 to 300 s" and "100 s either side of the turn" are
// at its 1 m/s), so every geometric answer is the same at any head speed. A question whose
// window reaches past the end of the valid motion is answered up to it, and says so; a table
// that runs past the first contact says from where its benches overlap.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dragon/analyses.hpp"
#include "dragon/executor.hpp"
#include "dragon/turnaround.hpp"
#include "dragon/window.hpp"

namespace dragon {

// The contest's questions: Q1 the coiling-in table, Q2 the first contact, Q3 the minimum pitch,
// Q4 the turnaround (its S-curve and table), Q5 the largest head speed.
enum class Question { q1, q2, q3, q4, q5 };

// Which questions to answer, over which windows and ranges, and on which threads.
struct ContestOptions {
    // The questions to answer (all five by default).
    std::vector<Question> questions{Question::q1, Question::q2, Question::q3, Question::q4, Question::q5};
    // Q1's table: 0 to 300 m of head travel, a row every second.
    RunWindow q1_window{Along::metres(0.0), Along::metres(300.0)};
    // Q3's pitch search: the range (unset: the contest's 0.35 to 0.55 m, moved up where the
    // scenario cannot use it; default_pitch_range) and the first scan's spacing.
    std::optional<double> pitch_lo;        // m
    std::optional<double> pitch_hi;        // m
    double pitch_grid = kDefaultPitchGrid;  // m
    // Q4's table and Q5's search: 100 m of head travel either side of the turn.
    RunWindow turn_window = kTurnaroundWindow;
    double speed_limit = 2.0;  // Q5, m/s
    // Called on a worker as soon as Q1's or Q4's table is ready (a workbook can be written while
    // the other questions are answered); it may throw, which ends the run with that error.
    std::function<void(const std::vector<Frame>&)> on_q1_table;
    // The same for Q4's table.
    std::function<void(const std::vector<Frame>&)> on_q4_table;
    Executor* executor = nullptr;  // null: the calling thread alone
    // Every search proves its answer (dragon solve --prove): Q2's first contact and Q4's check
    // step by step (ContactSearchOptions::prove_steps), Q3's every pitch (MinPitchOptions::prove),
    // Q5's largest speed (MaxSpeedOptions::prove). Opt-in: it about doubles the time of the
    // searches (docs/performance.md).
    bool prove = false;

    bool asks(Question q) const;  // whether `questions` holds q
};

// A table of frames at whole seconds over a window, cut to the valid motion.
struct ContestTable {
    std::vector<Frame> frames;  // one per whole second, in order
    Searched window;          // the window asked for, cut to the valid motion
    double asked_to = 0.0;    // s: the window's end as asked (before the cut)
    double asked_from = 0.0;  // s
    std::optional<Jam> jam;   // where the end of the valid motion cut it
    // The motion's first contact, when the table's rows run past it (the benches overlap from
    // there on); nullopt otherwise.
    std::optional<Contact> past_contact;
    int rows_left_out = 0;    // whole seconds of the window asked for that the cut leaves out
};

// Q3's range when none is given: the contest's [0.35, 0.55] m where every pitch in it can make a
// run to the boundary (above the bench width, the head starting outside the turning space);
// else from just above the smallest usable pitch to 1.5 times it, or 0.55 m if more. `moved`
// says the contest's range could not be used, and why.
struct PitchRange {
    double lo = 0.35;   // m
    double hi = 0.55;   // m
    std::string moved;  // "" for the contest's own range
};
PitchRange default_pitch_range(const Scenario& s);  // Q3's range for s, as above
// The range a minimum-pitch search of s covers: default_pitch_range(s) with the ends given in
// its place (`moved` only when an end it left to the default was moved). Every front end asks
// this, so min-pitch, solve, sweeps, Python and the page search the same pitches.
PitchRange pitch_search_range(const Scenario& s, std::optional<double> lo, std::optional<double> hi);

// Each question's answer, present when it was asked.
struct ContestAnswers {
    Scenario scenario;  // as solved (the path kind is each question's own)
    std::optional<ContestTable> q1;          // the coiling-in table
    std::optional<CollideAnswer> q2;         // the first contact
    std::optional<MinPitch> q3;              // the minimum pitch
    std::optional<PitchRange> q3_range;      // the range Q3 searched
    std::optional<SCurve> q4_design;         // the turnaround's S-curve
    std::optional<ContestTable> q4;          // the turnaround table
    std::optional<Jam> q4_jam;        // turnaround_jam: whether this dragon can follow the S-curve
    std::optional<ContactProof> q4_proof;  // with `prove`: what Q4's check for a contact in its window proved
    std::optional<MaxSpeed> q5;              // the largest head speed
};

// Answers the questions asked. Throws what the analyses throw for a value the scenario or the
// options make impossible (InputError: the same values the single commands refuse).
ContestAnswers solve_contest(const Scenario& s, const ContestOptions& options = {});

}  // namespace dragon
