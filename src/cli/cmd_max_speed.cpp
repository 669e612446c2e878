// dragon max-speed (Q5): the largest head speed with every handle at or under the limit.
#include <cmath>
#include <memory>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dragon/answers.hpp"
#include "commands.hpp"
#include "report.hpp"
#include "scenario_flags.hpp"
#include "status.hpp"
#include "window_flags.hpp"
#include "wording.hpp"
#include "dragon/tables.hpp"
#include "dragon/turnaround.hpp"

namespace dragon::cli {

namespace {

struct MaxSpeedFlags {
    ScenarioFlags scenario;
    double limit = 2.0;
    WindowFlags window;
    bool json = false;
    bool prove = false;
    bool quiet = false;  // it prints no status; taken as every command takes it
};
}  // namespace

void register_max_speed(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<MaxSpeedFlags>();
    CLI::App* sub = app.add_subcommand(
        "max-speed", "Q5: the largest head speed with every handle at or under the limit");
    opt->scenario.add_to(sub, ScenarioUse::turnaround_only(), reg);
    sub->add_option("--limit", opt->limit, "Handle speed limit, m/s (default 2)");
    opt->window.add_to(sub, "Search the Q4 run from here (default -100m: 100 s before the turn at 1 m/s)",
                       "Search up to here (default 100m)");
    sub->add_flag("--prove", opt->prove,
                  "Prove the largest speed: bound every handle's speed over every stretch of the window (slower; "
                  "without it the maximum is the scan's and its refinement's)");
    sub->add_flag("--json", opt->json, "Print one JSON object on stdout");
    add_quiet_flag(sub, opt->quiet);
    reg.runners["max-speed"] = [opt](ToolRun& run) {
        Executor& ex = run.executor;
        RunOutputs& outputs = run.outputs;
        Scenario s = opt->scenario.resolve(&outputs);
        s.path.kind = PathKind::turnaround;
        dragon::MaxSpeedOptions how;
        how.prove = opt->prove;
        const MaxSpeed m = max_head_speed(s, opt->limit, opt->window.resolve(kTurnaroundWindow), &ex, how);
        if (opt->json) {
            print_json(max_speed_answer(m, opt->limit));
            return 0;
        }
        if (m.unbounded) {
            fmt::print("No head speed keeps every handle at or under {} m/s: {}\n", opt->limit, jam_sentence(*m.jam));
            fmt::print("  as that moment nears, handle {}'s speed grows without bound, whatever the head's speed\n",
                       m.jam->handle);
            return 0;
        }
        if (m.jam) {
            // Cut short by the end of the valid motion: no speed makes the turn, so no headline speed.
            fmt::print("No head speed makes this turn: the dragon cannot follow the turnaround path through the "
                       "window at any speed: {}\n", jam_sentence(*m.jam));
            fmt::print("  (up to there, the fastest handle is {:.9f} times the head's speed, handle {} at t = {:.6f} s; "
                       "the largest head speed asked for is not defined)\n", m.ratio, m.handle, m.time);
            fmt::print("{}", window_cuts(m.window, "the search"));
            return 0;
        }
        fmt::print("Largest head speed with every handle at or under {} m/s: {} m/s\n", opt->limit,
                   format_amount(m.max_head_speed));
        fmt::print("  speed ratio (fastest handle / head, by magnitude): {:.9f}\n", m.ratio);
        std::string who = fmt::format("handle {}", m.handle);
        if (m.tied.size() > 1) who = fmt::format("handles {} (equal speeds)", fmt::join(m.tied, ", "));
        fmt::print("  reached by {} at t = {:.6f} s of the Q4 run (head {:.6f} m along the path "
                   "from the turn's start)\n", who, m.time, m.travel);
        fmt::print("  searched t = {}..{} s (the head from {} m to {} m along the path at {} m/s): coarse scan "
                   "every {:.4g} m, {} refined, {} solved\n", format_time(m.window.from),
                   format_time(m.window.to), format_time(m.window.from_travel), format_time(m.window.to_travel),
                   s.head_speed, m.scan_travel, count_of(m.candidates, "local maximum", "local maxima"),
                   count_of(m.evaluations, "chain"));
        fmt::print("{}", window_cuts(m.window, "the search"));
        fmt::print("{}", speed_proof_words(m));
        return 0;
    };
}

}  // namespace dragon::cli
