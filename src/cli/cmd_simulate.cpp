// dragon simulate: positions and exact speeds of every handle over a time range.
#include <cstdio>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/scenario_flags.hpp"
#include "dragon/analyses.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/tables.hpp"

namespace dragon::cli {

namespace {
struct SimulateOptions {
    ScenarioFlags scenario;
    std::optional<double> from, to;
    double step = 1.0;
    std::string out;
};
}  // namespace

void register_simulate(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<SimulateOptions>();
    CLI::App* sub = app.add_subcommand(
        "simulate", "Positions and exact speeds of every handle over time (Q1, Q4 tables)");
    opt->scenario.add_to(sub);
    sub->add_option("--from", opt->from, "First time, s (default 0; -100 on the turnaround path)");
    sub->add_option("--to", opt->to, "Last time, s (default 300; 100 on the turnaround path)");
    sub->add_option("--step", opt->step, "Time step, s (default 1)");
    sub->add_option("-o,--out", opt->out,
                    "Output file: .csv (long form), .json, or .xlsx (the contest's result1 layout); "
                    "CSV on stdout if omitted");
    reg["simulate"] = [opt]() {
        const Scenario s = opt->scenario.resolve();
        const bool turn = s.path.kind == PathKind::turnaround;
        const double t0 = opt->from.value_or(turn ? -100.0 : 0.0);
        const double t1 = opt->to.value_or(turn ? 100.0 : 300.0);
        if (!opt->out.empty()) {
            const std::string ext = extension_of(opt->out);
            if (ext != ".csv" && ext != ".json" && ext != ".xlsx")
                throw InputError(fmt::format("--out {} has extension '{}': use .csv, .json or .xlsx",
                                             opt->out, ext));
            AtomicFile probe(opt->out);  // fail on an unwritable path before any work
        }
        const Simulation sim(s);
        const std::vector<Frame> frames = simulate_table(sim, t0, t1, opt->step);
        if (!opt->out.empty() && extension_of(opt->out) == ".xlsx" && frames.size() > 16383)
            throw InputError(fmt::format("{} frames do not fit in one worksheet (at most 16383 "
                                         "columns): use a larger --step or .csv", frames.size()));
        if (opt->out.empty()) {
            std::fputs("t,handle,x,y,speed\n", stdout);
            for (const Frame& f : frames)
                for (size_t i = 0; i < f.handles.size(); ++i)
                    fmt::print("{},{},{:.6f},{:.6f},{:.6f}\n", format_time(f.time), i,
                               round6(f.handles[i].pos.x), round6(f.handles[i].pos.y),
                               round6(f.handles[i].speed));
        } else {
            write_table(frames, opt->out);
            fmt::print(stderr, "wrote {} ({} frames x {} handles)\n", opt->out, frames.size(),
                       frames.empty() ? 0 : frames.front().handles.size());
        }
        return 0;
    };
}

}  // namespace dragon::cli
