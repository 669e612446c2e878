// dragon solve: all five contest questions on one scenario: the workbooks, summary.json and
// the paper-style tables. The questions are the library's (dragon/contest.hpp): which windows
// and ranges, what runs in parallel, where the valid motion or a first contact cuts one short.
// This file has the flags, the words and the files.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dragon/answers.hpp"
#include "commands.hpp"
#include "report.hpp"
#include "scenario_flags.hpp"
#include "status.hpp"
#include "window_flags.hpp"
#include "wording.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/contest.hpp"
#include "dragon/contest_files.hpp"
#include "dragon/language.hpp"
#include "dragon/paper_tables.hpp"
#include "dragon/tables.hpp"

namespace dragon::cli {

namespace {

struct SolveOptions {
    ScenarioFlags scenario;
    std::string dir = "out";
    std::vector<std::string> only;
    std::optional<double> lo, hi;
    double grid = kDefaultPitchGrid;
    double limit = 2.0;
    WindowFlags window;
    std::string tables;  // latex, markdown or csv: the paper's tables as files beside the workbooks
    std::string lang = "en";
    bool prove = false;
    bool quiet = false;
};

// The frames of a table at every `every` seconds from its first, for the printed excerpt.
std::vector<const Frame*> pick(const std::vector<Frame>& frames, double every) {
    std::vector<const Frame*> out;
    if (frames.empty()) return out;
    const double first = frames.front().time;
    for (const Frame& f : frames)
        if (std::fmod(f.time - first, every) == 0.0) out.push_back(&f);
    return out;
}

// The scenario values the questions asked for read: a value none of them reads is not checked
// (a file's pitch does not matter to --only q4), and a flag for one is refused.
ScenarioValues values_read_by(const ContestOptions& o) {
    ScenarioValues v = 0;
    if (o.asks(Question::q1) || o.asks(Question::q2)) v |= values_read(PathKind::spiral);
    if (o.asks(Question::q3)) v |= value::bench | value::head_speed | value::start_turn | value::turn_radius;
    if (o.asks(Question::q4) || o.asks(Question::q5)) v |= values_read(PathKind::turnaround);
    return v;
}

// "rows 0..300 s" and, when the window was cut, what was left out and why (the end of the
// valid motion), and when rows run past the first contact, from where the benches overlap.
std::string table_notes(const ContestTable& t) {
    std::string out;
    if (t.rows_left_out > 0 && t.jam)
        out += fmt::format("\n  {} {} of {}..{} s left out: {}", t.rows_left_out, t.rows_left_out == 1 ? "row" : "rows",
                           format_time(t.asked_from), format_time(t.asked_to), jam_sentence(*t.jam));
    if (t.past_contact)
        out += fmt::format("\n  rows after t = {} s are past the first contact (bench {} touches bench {}): from "
                           "there on benches overlap", format_resolved(t.past_contact->time, t.past_contact->tolerance),
                           t.past_contact->bench_a, t.past_contact->bench_b);
    return out;
}

// Lines printed each indented by two spaces, under their answer.
void print_indented(const std::string& lines) {
    std::string out;
    for (size_t at = 0; at < lines.size();) {
        const size_t end = lines.find('\n', at);
        const size_t stop = end == std::string::npos ? lines.size() : end + 1;
        out += "  " + lines.substr(at, stop - at);
        at = stop;
    }
    fmt::print("{}", out);
}

}  // namespace

void register_solve(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<SolveOptions>();
    CLI::App* sub = app.add_subcommand(
        "solve", "All five questions: result1/2/4.xlsx, summary.json and the paper-style tables");
    opt->scenario.add_to(sub, ScenarioUse::both_paths("it answers Q1-Q3 on the plain spiral and Q4-Q5 on the "
                                                      "turnaround path"), reg);
    sub->add_option("-o,--out", opt->dir, "Output folder (created if missing; default out)");
    sub->add_option("--only", opt->only, "Answer only these questions: q1 q2 q3 q4 q5 (default all)")
        ->delimiter(',');
    sub->add_option("--lo", opt->lo, "Q3: smallest pitch searched, m (default 0.35, or just above the smallest "
                                     "pitch this dragon can start from)");
    sub->add_option("--hi", opt->hi, "Q3: largest pitch searched, m (default 0.55)");
    sub->add_option("--grid", opt->grid, "Q3: pitch spacing of the first scan, m (default 0.0025)");
    sub->add_option("--limit", opt->limit, "Q5: handle speed limit, m/s (default 2)");
    opt->window.add_to(sub, "Q4's table and Q5's search from here (default -100m: 100 s before the turn at 1 m/s)",
                       "Q4's table and Q5's search up to here (default 100m)");
    sub->add_option("--tables", opt->tables,
                    "Also write the paper's tables beside the workbooks, one file a table (table_q1_positions, "
                    "table_q1_speeds, table_q2_contact, table_q4_positions, table_q4_speeds, table_answers): latex "
                    "(.tex: booktabs, siunitx), markdown (.md, for pandoc) or csv");
    sub->add_option("--lang", opt->lang, "Language of the tables' headers and captions: en (default) or zh (the "
                                         "workbooks' words: 龙头x (m), 第1节龙身 (m/s))");
    sub->add_flag("--prove", opt->prove,
                  "Prove every answer as the single commands' --prove do: Q2's first contact and Q4's check step by "
                  "step, every pitch of Q3's range, Q5's largest speed bounded over the window (slower)");
    add_quiet_flag(sub, opt->quiet);
    reg.runners["solve"] = [opt](ToolRun& run) {
        Executor& ex = run.executor;
        RunOutputs& outputs = run.outputs;
        std::optional<TableFormat> table_format;
        if (!opt->tables.empty()) {
            if (opt->tables != "latex" && opt->tables != "markdown" && opt->tables != "csv")
                throw InputError(fmt::format("--tables {} is not allowed: use latex, markdown or csv", opt->tables));
            table_format = parse_table_format(opt->tables);
        }
        const Language lang = parse_language(opt->lang);
        if (opt->lang != "en" && !table_format)
            throw InputError(fmt::format("--lang {} is not used: only the tables of --tables have words in a "
                                         "language (the workbooks' are the contest's)", opt->lang));
        const std::set<std::string> all{"q1", "q2", "q3", "q4", "q5"};
        ContestOptions contest;
        if (!opt->only.empty()) contest.questions.clear();
        for (const std::string& q : opt->only) {
            if (!all.count(q))
                throw InputError(fmt::format("--only {} is not allowed: the questions are q1, q2, q3, q4, q5", q));
            contest.questions.push_back(static_cast<Question>(q[1] - '1'));
        }
        const auto refuse_unless = [&](bool given, Question q, const std::string& flag) {
            if (given && !contest.asks(q))
                throw InputError(fmt::format("{} is not used: no question of --only {} reads it", flag,
                                             fmt::join(opt->only, ",")));
        };
        refuse_unless(opt->lo || opt->hi, Question::q3, "--lo/--hi");
        refuse_unless(opt->grid != kDefaultPitchGrid, Question::q3, "--grid");
        refuse_unless(opt->limit != 2.0, Question::q5, "--limit");
        refuse_unless(opt->window.given() && !contest.asks(Question::q4), Question::q5, "--from/--to");
        if (opt->prove && contest.questions == std::vector<Question>{Question::q1})
            throw InputError("--prove is not used: no question of --only q1 searches for anything to prove (Q2-Q5 do)");
        Scenario s = opt->scenario.resolve(values_read_by(contest),
                                           fmt::format("no question of --only {} reads it", fmt::join(opt->only, ",")),
                                           &outputs);
        contest.pitch_lo = opt->lo;
        contest.pitch_hi = opt->hi;
        contest.pitch_grid = opt->grid;
        contest.speed_limit = opt->limit;
        contest.turn_window = opt->window.resolve(kTurnaroundWindow);
        contest.prove = opt->prove;

        // Every target checked, and its temporary file made, before any work; the workbooks of
        // Q1 and Q4 written while the other questions are answered; the set put in place together.
        ContestFiles files(opt->dir, contest, table_format, lang, kWorkbooks, &outputs);
        files.attach(contest);
        contest.executor = &ex;
        const ContestAnswers a = solve_contest(s, contest);

        // Q1: coiling in.
        if (const std::optional<ContestTable>& q1 = a.q1) {
            print_frame_table(fmt::format("Q1: positions (m) and speeds (m/s) while coiling in, t = {}..{} s{}",
                                          q1->frames.empty() ? "-" : format_time(q1->frames.front().time),
                                          q1->frames.empty() ? "-" : format_time(q1->frames.back().time),
                                          table_notes(*q1)),
                              pick(q1->frames, 60.0 / s.head_speed == std::round(60.0 / s.head_speed)
                                                   ? 60.0 / s.head_speed : 60.0));
        }

        // Q2: the termination time.
        if (const std::optional<CollideAnswer>& q2 = a.q2) {
            if (q2->overlap) {
                fmt::print("\nQ2: the chain collides before it moves: {}\n",
                           overlap_sentence(*q2->overlap, q2->asked.from));
                print_single_frame("", q2->contact->frame);
            } else if (const std::optional<Contact>& c = q2->contact) {
                fmt::print("\nQ2: benches {} and {} touch at t = {} s (head radius {:.6f} m)\n", c->bench_a,
                           c->bench_b, format_resolved(c->time, c->tolerance), c->head_radius);
                if (opt->prove) fmt::print("  {}", proof_words(c->proof, &*c));
                print_single_frame("", c->frame);
            } else {
                fmt::print("\nQ2: no collision as far as the dragon can follow the spiral (t = {} s){}\n",
                           format_time(q2->window.to), q2->jam ? ": " + jam_sentence(*q2->jam) : "");
                if (opt->prove) fmt::print("  {}", proof_words(q2->proof, nullptr));
            }
        }

        // Q3: the minimum pitch.
        if (const std::optional<MinPitch>& q3 = a.q3) {
            const MinPitch& m = *q3;
            if (!a.q3_range->moved.empty())
                fmt::print("\nQ3: searched {}..{} m: {}", m.search_lo, m.search_hi, a.q3_range->moved);
            // Resolved to 1e-9 m: ten decimals.
            if (std::isnan(m.pitch))
                fmt::print("\nQ3: no change from collision to collision-free in {}..{} m (the minimum pitch lies {})\n",
                           m.search_lo, m.search_hi,
                           m.below_range ? fmt::format("at or below {} m", m.search_lo)
                                         : fmt::format("above {} m", m.search_hi));
            else
                fmt::print("\nQ3: minimum pitch {:.10f} m to reach radius {} m collision-free\n", m.pitch,
                           s.path.turn_radius);
            for (const PitchInterval& i : m.intervals)
                fmt::print("  [{:.10f}, {:.10f}] m  {}\n", i.lo, i.hi, i.feasible ? "collision-free" : "collides");
            if (m.jam)
                fmt::print("  at pitch {} m (the largest of the scan where this happens) the dragon cannot follow the "
                           "spiral to radius {} m at all: {}\n", m.jam->pitch, s.path.turn_radius,
                           jam_sentence(m.jam->jam));
            if (opt->prove) print_indented(pitch_proof_words(m));
        }

        // Q4: the S-curve and the table around the turn.
        if (const std::optional<ContestTable>& q4 = a.q4) {
            const SCurve& sc = *a.q4_design;
            fmt::print("\nQ4: S-curve r1 = {:.6f} m, r2 = {:.6f} m, length {:.6f} m{}\n", sc.r1, sc.r2, sc.length,
                       a.q4_jam ? "; this dragon cannot follow it: " + jam_sentence(*a.q4_jam) : "");
            print_frame_table(fmt::format("Q4: positions (m) and speeds (m/s) around the turn, t = {}..{} s{}",
                                          q4->frames.empty() ? "-" : format_time(q4->frames.front().time),
                                          q4->frames.empty() ? "-" : format_time(q4->frames.back().time),
                                          table_notes(*q4)),
                              pick(q4->frames, 50.0 / s.head_speed == std::round(50.0 / s.head_speed)
                                                   ? 50.0 / s.head_speed : 50.0));
            if (a.q4_proof)
                fmt::print("  the window checked for a contact: {}",
                           proof_words(*a.q4_proof, q4->past_contact ? &*q4->past_contact : nullptr));
        }

        // Q5: the speed limit.
        if (const std::optional<MaxSpeed>& q5 = a.q5) {
            const MaxSpeed& v = *q5;
            if (v.unbounded)
                fmt::print("\nQ5: no head speed keeps every handle at or under {} m/s: {}\n", contest.speed_limit,
                           jam_sentence(*v.jam));
            else if (v.jam)
                fmt::print("\nQ5: no head speed makes this turn: the dragon cannot follow the turnaround path "
                           "through the window at any speed: {}\n", jam_sentence(*v.jam));
            else
                fmt::print("\nQ5: largest head speed {:.6f} m/s (speed ratio {:.6f} at handle {}, t = {:.6f} s)\n",
                           v.max_head_speed, v.ratio, v.handle, v.time);
            if (opt->prove && !v.unbounded && !v.jam) fmt::print("  {}", speed_proof_words(v));
        }
        require_stdout_written();  // the tables all printed, or no file changes
        files.finish(a, json_text(contest_summary(a, contest), 2) + "\n");
        run.wrote(opt->quiet, "wrote {} in {}", fmt::join(files.names(), ", "), opt->dir);
        return 0;
    };
}

}  // namespace dragon::cli
