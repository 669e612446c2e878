// dragon simulate: positions and exact speeds of every handle over a time range.
#include <cstdio>

#include <fmt/format.h>

#include "commands.hpp"
#include "report.hpp"
#include "scenario_flags.hpp"
#include "status.hpp"
#include "window_flags.hpp"
#include "wording.hpp"
#include "dragon/analyses.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/language.hpp"
#include "dragon/paper_tables.hpp"
#include "dragon/tables.hpp"

namespace dragon::cli {

namespace {
struct SimulateOptions {
    ScenarioFlags scenario;
    WindowFlags window;
    double step = 1.0;
    std::string out;
    std::optional<int> digits;
    std::string table;  // latex, markdown or csv: the paper-style tables of the frames instead
    std::string lang = "en";
    bool quiet = false;
};

// The most frames a paper-style table shows: one column each.
constexpr std::size_t kMaxTableFrames = 20;
}  // namespace

void register_simulate(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<SimulateOptions>();
    CLI::App* sub = app.add_subcommand(
        "simulate",
        "Positions and exact speeds of every handle over time (Q1, Q4 tables). Speeds are signed along the path: "
        "negative while a handle backs up. Times past the end of the dragon's valid motion (where a handle would "
        "have to jump) are refused");
    opt->scenario.add_to(sub, ScenarioUse::either_path(), reg);
    opt->window.add_to(sub, "First moment (default 0; -100m on the turnaround path)",
                       "Last moment (default 300m: 300 s at 1 m/s; 100m on the turnaround path; at most the end of "
                       "the valid motion). The table ends exactly at it when the steps from --from land on it (up "
                       "to rounding), else at the last step before it");
    sub->add_option("--step", opt->step, "Time step, s (default 1)");
    sub->add_option("-o,--out", opt->out,
                    "Output file: .csv (long form), .json, or .xlsx (the contest's result1 layout); "
                    "CSV on stdout if omitted");
    sub->add_option("--digits", opt->digits, "Decimals of every number in CSV and JSON (t without trailing zeros), 0 to 17 (default 6)");
    sub->add_option("--table", opt->table,
                    "Instead of every handle, the paper-style tables of handles 0, 1, 51, 101, 151, 201 and the "
                    "tail's rear handle, a column per frame (at most 20: choose --step), positions then speeds: latex "
                    "(booktabs, siunitx), markdown (pandoc) or csv; on stdout, or -o FILE.tex, .md or .csv");
    sub->add_option("--lang", opt->lang, "With --table, the language of its headers and captions: en (default) or zh");
    add_quiet_flag(sub, opt->quiet);
    reg.runners["simulate"] = [opt](ToolRun& run) {
        Executor& ex = run.executor;
        RunOutputs& outputs = run.outputs;
        const std::string ext = opt->out.empty() ? ".csv" : extension_of(opt->out);
        std::optional<TableFormat> table;
        if (!opt->table.empty()) {
            if (opt->table != "latex" && opt->table != "markdown" && opt->table != "csv")
                throw InputError(fmt::format("--table {} is not allowed: use latex, markdown or csv", opt->table));
            table = parse_table_format(opt->table);
            if (!opt->out.empty() && ext != table_extension(*table))
                throw InputError(fmt::format("--out {} has extension '{}': --table {} writes {}", opt->out, ext,
                                             opt->table, table_extension(*table)));
            if (opt->digits)
                throw InputError(fmt::format("--digits {} is not allowed with --table: the tables hold 6 decimals, "
                                             "as the workbooks", *opt->digits));
        } else if (opt->lang != "en") {
            throw InputError(fmt::format("--lang {} is not used: only --table has words in a language", opt->lang));
        }
        const Language lang = parse_language(opt->lang);
        if (!table && !opt->out.empty() && ext != ".csv" && ext != ".json" && ext != ".xlsx")
            throw InputError(fmt::format("--out {} has extension '{}': use .csv, .json or .xlsx", opt->out, ext));
        if (opt->digits && ext == ".xlsx")
            throw InputError(fmt::format("--digits {} is not allowed with .xlsx: the contest's workbooks hold 6 "
                                         "decimals (use .csv or .json for more)", *opt->digits));
        const int digits = checked_digits(opt->digits);
        const Scenario s = opt->scenario.resolve(&outputs);
        const bool turn = s.path.kind == PathKind::turnaround;
        // The contest's runs, as head travel: 300 m coiling in, 100 m either side of the turn.
        const RunWindow window = opt->window.resolve(
            turn ? kTurnaroundWindow : RunWindow{Along::metres(0.0), Along::metres(300.0)});
        if (!opt->out.empty()) AtomicFile probe(opt->out, &outputs);  // an unwritable path fails here, before any work
        const Simulation sim(s);
        require_valid_at(sim, window.from, Key::from);
        require_valid_at(sim, window.to, Key::to);
        const double t0 = window.from.time(s.head_speed), t1 = window.to.time(s.head_speed);
        const std::vector<Frame> frames = simulate_table(sim, t0, t1, opt->step, &ex);
        require_distinct_times(frames, digits, ext == ".xlsx");  // no two rows labelled with one moment
        // Rows past the first contact show benches lying across each other: said on stderr.
        const CollideAnswer contact = first_contact_covering(sim, t0, t1, &ex);
        if (const std::optional<Contact>& c = contact.contact; c && !frames.empty() && frames.back().time > c->time)
            fmt::print(stderr, "dragon: note: rows {} t = {} s are past the first contact (bench {} touches bench "
                               "{}): from there on benches overlap\n", contact.overlapping ? "from" : "after",
                       format_resolved(c->time, c->tolerance), c->bench_a, c->bench_b);
        if (ext == ".xlsx" && frames.size() > kMaxWorkbookFrames)
            throw InputError(fmt::format("{} frames do not fit in one worksheet (at most {} "
                                         "columns): use a larger --step or .csv", frames.size(), kMaxWorkbookFrames));
        if (table) {
            if (frames.size() > kMaxTableFrames)
                throw InputError(fmt::format("--table is not allowed with {} frames: a table shows at most {} "
                                             "(a column each): use a larger --step", frames.size(), kMaxTableFrames));
            PaperTable pos = positions_table(frames, lang), speeds = speeds_table(frames, lang);
            pos.id = "positions", speeds.id = "speeds";
            pos.label = "tab:dragon-positions", speeds.label = "tab:dragon-speeds";
            std::string text;
            if (*table == TableFormat::csv) {
                // One CSV: the speeds' rows under the positions', the same columns.
                pos.rows.insert(pos.rows.end(), speeds.rows.begin(), speeds.rows.end());
                text = format_table(pos, *table);
            } else {
                text = format_table(pos, *table) + "\n" + format_table(speeds, *table);
            }
            if (opt->out.empty()) {
                fmt::print("{}", text);
                return 0;
            }
            AtomicFile out(opt->out, &outputs);
            write_text_file(out, text);
            out.commit();
            run.wrote(opt->quiet, "wrote {} ({})", opt->out, count_of(static_cast<long long>(frames.size()), "frame"));
            return 0;
        }
        if (opt->out.empty()) {
            print_csv(frames, stdout, digits);
            return 0;
        }
        write_table(frames, opt->out, digits, kWorkbooks, &outputs);
        run.wrote(opt->quiet, "wrote {} ({} x {})", opt->out, count_of(static_cast<long long>(frames.size()), "frame"),
               count_of(frames.empty() ? 0 : static_cast<long long>(frames.front().handles.size()), "handle"));
        return 0;
    };
}

}  // namespace dragon::cli
