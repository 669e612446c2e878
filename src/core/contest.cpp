// The contest's five questions on one scenario (dragon/contest.hpp).
#include "dragon/contest.hpp"

#include <algorithm>
#include <array>
#include <exception>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace dragon {

namespace {

// Rows at whole seconds over the window cut to the valid motion.
ContestTable table_over(const Simulation& sim, const RunWindow& window, Executor* executor) {
    const double v = sim.scenario().head_speed;
    const WindowCut cut = cut_window(sim, window);
    ContestTable out;
    out.window = cut.searched(v);
    out.jam = cut.after ? cut.after : cut.before;
    out.asked_from = window.from.time(v);
    out.asked_to = window.to.time(v);
    // A window end given in travel lands on a whole second up to the division's rounding (300 m
    // at 0.3 m/s is 1000 s, or a hair under): such an end counts as that second, unless the
    // end is a jam's, which no row may pass.
    constexpr double kSlack = 1e-9;
    const double first = std::ceil(out.window.from - (cut.before ? 0.0 : kSlack * std::abs(out.window.from)));
    const double last = std::floor(out.window.to + (cut.after ? 0.0 : kSlack * std::abs(out.window.to)));
    const double asked_rows = std::floor(out.asked_to + kSlack * std::abs(out.asked_to)) -
                              std::ceil(out.asked_from - kSlack * std::abs(out.asked_from)) + 1.0;
    if (last >= first) {
        out.frames = simulate_table(sim, first, last, 1.0, executor);
        // The rows at the ends are the whole seconds themselves, within the window.
    }
    out.rows_left_out = static_cast<int>(std::max(0.0, asked_rows - static_cast<double>(out.frames.size())));
    return out;
}

// The motion's first contact, when the table runs past it.
void mark_past_contact(ContestTable& table, const std::optional<Contact>& contact) {
    if (contact && !table.frames.empty() && table.frames.back().time > contact->time) table.past_contact = contact;
}

}  // namespace

bool ContestOptions::asks(Question q) const { return std::find(questions.begin(), questions.end(), q) != questions.end(); }

PitchRange default_pitch_range(const Scenario& s) {
    PitchRange r;
    // The head must start outside the turning space (r = pitch * start_turn), and the pitch
    // exceed the bench width.
    const double start_limit = s.path.turn_radius / s.path.start_turn;
    const double floor = std::max(s.bench.width, start_limit);
    if (r.lo > floor) return r;
    r.lo = std::strtod(fmt::format("{:.6g}", floor * (1.0 + 1e-6)).c_str(), nullptr);
    if (!(r.lo > floor)) r.lo = std::nextafter(floor, INFINITY);
    r.hi = std::max(0.55, 1.5 * r.lo);
    r.moved = floor == s.bench.width
                  ? fmt::format("the contest's 0.35..0.55 m would put the turns closer than the bench width, {} m",
                                s.bench.width)
                  : fmt::format("below {} m the head would start inside the turning space (start turn {}, radius {} m)",
                                fmt::format("{:.6g}", start_limit), s.path.start_turn, s.path.turn_radius);
    return r;
}

PitchRange pitch_search_range(const Scenario& s, std::optional<double> lo, std::optional<double> hi) {
    PitchRange r = default_pitch_range(s);
    if (lo && hi) r.moved.clear();
    if (lo) r.lo = *lo;
    if (hi) r.hi = *hi;
    return r;
}

ContestAnswers solve_contest(const Scenario& scenario, const ContestOptions& options) {
    ContestAnswers out;
    out.scenario = scenario;
    Scenario coil = scenario;
    coil.path.kind = PathKind::spiral;
    Scenario turn = scenario;
    turn.path.kind = PathKind::turnaround;
    // Only the simulations a question asked for: --only q4 reads no value of the plain spiral,
    // which may not even make one.
    std::optional<Simulation> coil_sim, turn_sim;
    if (options.asks(Question::q1) || options.asks(Question::q2)) coil_sim.emplace(coil);
    if (options.asks(Question::q4) || options.asks(Question::q5)) turn_sim.emplace(turn);
    if (options.asks(Question::q3)) {
        out.q3_range = pitch_search_range(coil, options.pitch_lo, options.pitch_hi);
    }

    // The jobs, longest first, spread over the executor's workers; the parallel work inside a
    // job (Q3's pitches, Q1's frames) goes to the same workers, which take it up as they finish
    // their own questions. Q1 needs Q2's contact to mark rows past it, so Q2 runs first in Q1's
    // job.
    enum Job { q3, q1_q2, q4, q5, count };
    InlineExecutor serial;
    Executor& ex = executor_or(options.executor, serial);
    Executor* const inside = &ex;
    // A run that fails in several jobs (a full disk under two workbooks closing at once) reports
    // the first question's failure, whichever worker met its own first.
    std::array<std::exception_ptr, count> failed;
    ex.parallel_for(count, [&](std::size_t job, int) {
        try {
            switch (static_cast<Job>(job)) {
                case q3:
                    if (options.asks(Question::q3)) {
                        MinPitchOptions o;
                        o.grid = options.pitch_grid;
                        o.executor = inside;
                        o.prove = options.prove;
                        out.q3 = min_pitch(coil, out.q3_range->lo, out.q3_range->hi, o);
                    }
                    break;
                case q1_q2:
                    if (options.asks(Question::q1) || options.asks(Question::q2)) {
                        ContactSearchOptions o;
                        o.executor = inside;
                        o.prove_steps = options.prove;
                        out.q2 = first_contact_of_motion(*coil_sim, o);
                    }
                    if (options.asks(Question::q1)) {
                        out.q1 = table_over(*coil_sim, options.q1_window, inside);
                        mark_past_contact(*out.q1, out.q2->contact);
                        if (options.on_q1_table) options.on_q1_table(out.q1->frames);
                    }
                    if (!options.asks(Question::q2)) out.q2.reset();
                    break;
                case q4:
                    if (options.asks(Question::q4)) {
                        out.q4_design = design_s_curve(turn);
                        out.q4_jam = turnaround_jam(*turn_sim);
                        out.q4 = table_over(*turn_sim, options.turn_window, inside);
                        ContactSearchOptions o;
                        o.executor = inside;
                        o.prove_steps = options.prove;
                        if (options.prove) o.proof = &out.q4_proof.emplace();
                        mark_past_contact(*out.q4, first_contact_travel(*turn_sim, out.q4->window.from_travel,
                                                                        out.q4->window.to_travel, o));
                        if (options.on_q4_table) options.on_q4_table(out.q4->frames);
                    }
                    break;
                case q5:
                    if (options.asks(Question::q5)) {
                        MaxSpeedOptions o;
                        o.prove = options.prove;
                        out.q5 = max_head_speed(turn, options.speed_limit, options.turn_window, inside, o);
                    }
                    break;
                case count: break;
            }
        } catch (...) {
            failed[job] = std::current_exception();
        }
    });
    for (const Job job : {q1_q2, q3, q4, q5})
        if (failed[job]) std::rethrow_exception(failed[job]);
    return out;
}

}  // namespace dragon
