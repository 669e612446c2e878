// dragon simulate: positions and exact speeds of every handle over a time range.
#include <cstdio>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/report.hpp"
#include "cli/scenario_flags.hpp"
#include "cli/status.hpp"
#include "cli/wording.hpp"
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
    std::optional<int> digits;
    bool quiet = false;
};
}  // namespace

void register_simulate(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<SimulateOptions>();
    CLI::App* sub = app.add_subcommand(
        "simulate",
        "Positions and exact speeds of every handle over time (Q1, Q4 tables). Speeds are signed along the path: "
        "negative while a handle backs up. Times past the end of the dragon's valid motion (where a handle would "
        "have to jump) are refused");
    opt->scenario.add_to(sub, ScenarioUse::either_path());
    sub->add_option("--from", opt->from, "First time, s (default 0; -100 on the turnaround path)");
    sub->add_option("--to", opt->to,
                    "Last time, s (default 300; 100 on the turnaround path; at most the end of the valid motion). "
                    "The table ends exactly at it when "
                    "the steps from --from land on it (up to rounding), else at the last step before it");
    sub->add_option("--step", opt->step, "Time step, s (default 1)");
    sub->add_option("-o,--out", opt->out,
                    "Output file: .csv (long form), .json, or .xlsx (the contest's result1 layout); "
                    "CSV on stdout if omitted");
    sub->add_option("--digits", opt->digits, "Decimals of every number in CSV and JSON (t without trailing zeros), 0 to 17 (default 6)");
    add_quiet_flag(sub, opt->quiet);
    reg["simulate"] = [opt]() {
        const std::string ext = opt->out.empty() ? ".csv" : extension_of(opt->out);
        if (!opt->out.empty() && ext != ".csv" && ext != ".json" && ext != ".xlsx")
            throw InputError(fmt::format("--out {} has extension '{}': use .csv, .json or .xlsx", opt->out, ext));
        if (opt->digits && ext == ".xlsx")
            throw InputError(fmt::format("--digits {} is not allowed with .xlsx: the contest's workbooks hold 6 "
                                         "decimals (use .csv or .json for more)", *opt->digits));
        const int digits = checked_digits(opt->digits);
        const Scenario s = opt->scenario.resolve();
        const bool turn = s.path.kind == PathKind::turnaround;
        const double t0 = opt->from.value_or(turn ? -100.0 : 0.0);
        const double t1 = opt->to.value_or(turn ? 100.0 : 300.0);
        if (!opt->out.empty()) AtomicFile probe(opt->out);  // an unwritable path fails here, before any work
        const Simulation sim(s);
        const std::vector<Frame> frames = simulate_table(sim, t0, t1, opt->step);
        if (ext == ".xlsx" && frames.size() > kMaxWorkbookFrames)
            throw InputError(fmt::format("{} frames do not fit in one worksheet (at most {} "
                                         "columns): use a larger --step or .csv", frames.size(), kMaxWorkbookFrames));
        if (opt->out.empty()) {
            print_csv(frames, stdout, digits);
            return 0;
        }
        write_table(frames, opt->out, digits);
        status(opt->quiet, "wrote {} ({} x {})", opt->out, count_of(static_cast<long long>(frames.size()), "frame"),
               count_of(frames.empty() ? 0 : static_cast<long long>(frames.front().handles.size()), "handle"));
        return 0;
    };
}

}  // namespace dragon::cli
