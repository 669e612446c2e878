// dragon turnaround (Q4): the S-curve's design, whether it can be shorter, and how close the
// benches come on the way through it.
#include <cmath>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "dragon/answers.hpp"
#include "dragon/turnaround_csv.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "report.hpp"
#include "scenario_flags.hpp"
#include "wording.hpp"
#include "status.hpp"
#include "window_flags.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/tables.hpp"
#include "dragon/turnaround.hpp"

namespace dragon::cli {

namespace {

constexpr double kDegrees = 57.295779513082320876798154814105;

struct TurnaroundOptions {
    ScenarioFlags scenario;
    bool json = false;
    bool skip_clearance = false;
    bool prove = false;
    WindowFlags window;
    std::string out;
    bool quiet = false;
};

// "yes", or "no: handle 1 jumps at t = 15.147713 s".
std::string followable(const TurnStudyRow& r) {
    if (!r.jam) return "yes";
    return fmt::format("no: handle {} {} at t = {:.6f} s", r.jam->handle,
                       r.jam->kind == JamKind::root_vanishes ? "loses its root" : "jumps to a nearer root", r.jam->time);
}

void print_text(const TurnaroundStudy& st, const std::optional<RunClearance>& clear) {
    const SCurve& d = st.design;
    fmt::print("Turnaround S-curve (pitch {} m, turning space radius {} m, r1/r2 = {})\n", d.pitch,
               d.entry_radius, d.ratio);
    fmt::print("  entry A   ({:.6f}, {:.6f})    exit B ({:.6f}, {:.6f})\n", d.entry.x(), d.entry.y(),
               d.exit.x(), d.exit.y());
    fmt::print("  arc 1     centre ({:.6f}, {:.6f})  r1 = {:.6f} m  {:.6f} rad ({:.2f} deg)  {:.6f} m\n",
               d.c1.x(), d.c1.y(), d.r1, d.angle1, d.angle1 * kDegrees, d.length1);
    fmt::print("  arc 2     centre ({:.6f}, {:.6f})  r2 = {:.6f} m  {:.6f} rad ({:.2f} deg)  {:.6f} m\n",
               d.c2.x(), d.c2.y(), d.r2, d.angle2, d.angle2 * kDegrees, d.length2);
    fmt::print("  joint     ({:.6f}, {:.6f})\n", d.joint.x(), d.joint.y());
    fmt::print("  length    {:.6f} m (farthest from the centre: {:.6f} m)\n", d.length, d.max_radius);
    if (st.design_jam) fmt::print("  this dragon cannot follow it: {}\n", jam_sentence(*st.design_jam));
    fmt::print("\nCan the turning curve be shorter? (and can this dragon follow it?)\n");
    fmt::print("  {:>7}  {:>10}  {:>10}  {:>14}  {}\n", "r1/r2", "r1 (m)", "r2 (m)", "S-curve (m)", "followable");
    for (const TurnStudyRow& r : st.by_ratio)
        fmt::print("  {:>7.3f}  {:>10.6f}  {:>10.6f}  {:>14.9f}  {}\n", r.ratio, r.r1, r.r2, r.s_curve_length,
                   followable(r));
    fmt::print("\n  {:>12}  {:>14}  {:>22}  {}\n", "entry r (m)", "S-curve (m)", "inside the space (m)", "followable");
    for (const TurnStudyRow& r : st.by_entry)
        fmt::print("  {:>12.4f}  {:>14.6f}  {:>22.6f}  {}\n", r.entry_radius, r.s_curve_length, r.inside_length,
                   followable(r));
    fmt::print("\n  {}\n", turnaround_conclusion(st));

    if (!clear) return;
    const Searched& w = clear->window;
    const std::string range = fmt::format("t = {}..{} s (head travel {}..{} m)", format_time(w.from),
                                          clear->jam && clear->jam->ahead ? format_resolved(w.to, clear->jam->tolerance)
                                                                          : format_time(w.to),
                                          format_time(w.from_travel), format_time(w.to_travel));
    if (const std::optional<Contact>& c = clear->first_contact) {
        fmt::print("\nFirst contact over {}: bench {} touches bench {} at t = {} s (head travel {} m), at "
                   "({:.6f}, {:.6f}); benches COLLIDE\n", range, c->bench_a, c->bench_b,
                   format_resolved(c->time, c->tolerance), format_resolved(c->travel, c->travel_tolerance),
                   c->point.x(), c->point.y());
    } else if (clear->bench_a == 0) {
        fmt::print("\nClearance over {}: no two benches come within {:.6f} m; collision-free\n", range,
                   clear->distance);
    } else {
        fmt::print("\nClearance over {}: smallest {:.6f} m, benches {} and {} at t = {:.6f} s; collision-free\n",
                   range, clear->distance, clear->bench_a, clear->bench_b, clear->time);
    }
    fmt::print("{}", window_cuts(w, "the check"));
    fmt::print("{}", proof_words(clear->proof, clear->first_contact ? &*clear->first_contact : nullptr));
    if (const std::optional<ClearanceProof>& p = clear->clearance_proof) {
        // The steps' enclosures assume the valid motion: where its own proof left steps to their
        // rates (near the end of the valid motion), the bound rests on those too.
        const JamSearchStats& m = clear->proof.motion;
        const std::string given =
            clear->proof.motion_checked && m.unproved_steps > 0
                ? fmt::format("; over the valid motion's {} m of head travel left to the rate check, given that motion",
                              format_amount(m.unproved_travel))
                : std::string();
        // The clearance found is a moment's own, so the least lies between the bound and it.
        if (p->proved && clear->bench_a == 0)  // no pair within the scan's cutoff: a bound, no moment
            fmt::print("proved: no two benches come closer than {:.9f} m anywhere in the window ({} enclosing every "
                       "bench{})\n", rounded_to(p->lower, 9, false), count_of(p->steps, "step", "steps"), given);
        else if (p->proved)
            fmt::print("proved: the smallest clearance lies in {} m (no two benches come closer than its lower end "
                       "anywhere in the window: {} enclosing every bench{})\n",
                       proved_interval(p->lower, clear->distance, 9), count_of(p->steps, "step", "steps"), given);
        else
            fmt::print("not proved: that no two benches come closer than {:.9f} m (a step could not be enclosed that "
                       "closely); the smallest clearance rests on the scan and its refinement\n", p->lower);
    }
}

}  // namespace

void register_turnaround(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<TurnaroundOptions>();
    CLI::App* sub = app.add_subcommand(
        "turnaround", "Q4: the S-curve turnaround, whether it can be shorter, and its clearance");
    opt->scenario.add_to(sub, ScenarioUse::turnaround_only(), reg);
    sub->add_flag("--json", opt->json, "Print one JSON object on stdout");
    sub->add_option("-o,--out", opt->out, "Write the length study as CSV to this file");
    auto* skip = sub->add_flag("--no-clearance", opt->skip_clearance,
                               "Skip the check for a first contact and the clearance before it");
    auto* prove = sub->add_flag("--prove", opt->prove,
                                "Prove the check: enclose every bench over each step of the first-contact search, and the smallest clearance to 1e-6 m (slower)");
    prove->excludes(skip);
    // The window is the check's: without the check it would do nothing.
    opt->window.add_to(sub, "Check from here (default -100m: 100 s before the turn at 1 m/s)",
                       "Check up to here (default 100m)");
    opt->window.from_option()->excludes(skip);
    opt->window.to_option()->excludes(skip);
    add_quiet_flag(sub, opt->quiet);
    reg.runners["turnaround"] = [opt](ToolRun& run) {
        Executor& ex = run.executor;
        RunOutputs& outputs = run.outputs;
        Scenario s = opt->scenario.resolve(&outputs);
        s.path.kind = PathKind::turnaround;
        if (!opt->out.empty() && extension_of(opt->out) != ".csv")
            throw InputError(fmt::format("--out {} is not allowed: the length study is written as .csv",
                                         opt->out));
        const RunWindow window = opt->window.resolve(kTurnaroundWindow);
        if (!opt->out.empty()) AtomicFile probe(opt->out, &outputs);  // fail on an unwritable path first
        const TurnaroundStudy st = study_turnaround(s);
        std::optional<RunClearance> clear;
        if (!opt->skip_clearance) {
            ProgressLine progress("samples", opt->quiet);  // long chains and fast heads take seconds
            clear = min_clearance(s, window,
                                  [&progress](std::int64_t done, std::int64_t total) { progress.update(done, total); }, &ex,
                                  opt->prove);
        }
        if (!opt->out.empty()) write_study_csv(st, opt->out, &outputs);
        if (opt->json) print_json(turnaround_answer(st.design, st.design_jam, clear, &st));
        else print_text(st, clear);
        if (!opt->out.empty()) run.wrote(opt->quiet, "wrote {}", opt->out);
        return 0;
    };
}

}  // namespace dragon::cli
