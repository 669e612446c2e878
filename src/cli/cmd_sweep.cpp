// dragon sweep: the answers mapped over the design space; dragon sweep merge: a sweep's parts
// joined. Thin: the grid, rows, their files, resuming and merging are the library's
// (dragon/sweep.hpp, sweep_setup.hpp, sweep_files.hpp); here are the flags, stdout and stderr.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "commands.hpp"
#include "scenario_flags.hpp"
#include "progress.hpp"
#include "report.hpp"
#include "status.hpp"
#include "sweep_plot.hpp"
#include "sweep_setup.hpp"
#include "wording.hpp"
#include "print_flags.hpp"
#include "render_flags.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/sweep_files.hpp"

namespace dragon::cli {

namespace {

struct SweepOptions {
    ScenarioFlags scenario;
    SweepRequest request;
    SweepOutputRequest output;  // -o, --resume
    bool json = false;          // each row as a JSON object on stdout
    bool quiet = false;
    std::string plot;
    PrintFlags print;  // the map's size on a page
    std::string lang = "en", merge_lang = "en";  // the map's words
    std::optional<int> workers;
    // dragon sweep merge
    CLI::App* merge = nullptr;
    std::vector<std::string> merge_files;  // OUT.csv, then the parts
    std::string merge_plot;
    PrintFlags merge_print;
    bool merge_quiet = false;
};

void write_plot(const std::string& path, const MapCollector& maps, const std::optional<PrintSize>& print,
                Language language, bool quiet, ToolRun& run) {
    write_sweep_map(maps.map(language), path, print, &run.outputs);
    run.wrote(quiet, "wrote {}", path);
}

// The print size for --plot, checked before any row is computed.
std::optional<PrintSize> plot_print(const PrintFlags& flags, const std::string& plot) {
    const std::optional<PrintSize> print = flags.resolve();
    if (print && plot.empty())
        throw InputError("a print size (--print, --width-in, --width-cm, --font-pt, --dpi) sizes the map: give --plot");
    return print;
}

int run_merge(const SweepOptions& opt, ToolRun& run) {
    RunOutputs& outputs = run.outputs;
    for (const std::string& extra : opt.merge->remaining())
        throw InputError(fmt::format("dragon sweep merge has no option {} (see dragon sweep merge --help)", extra));
    for (const std::string& f : opt.merge_files)
        if (f.empty()) throw InputError("dragon sweep merge '' is not allowed: give a file name");
    if (opt.merge_files.size() < 2)
        throw InputError("dragon sweep merge needs OUT.csv and the files to merge: dragon sweep merge OUT.csv PART.csv...");
    const std::string out = opt.merge_files.front();
    const std::vector<std::string> parts(opt.merge_files.begin() + 1, opt.merge_files.end());
    const SweepSetup whole = whole_sweep(parts, &outputs);
    const std::optional<PrintSize> print = plot_print(opt.merge_print, opt.merge_plot);
    const Language language = parse_language(opt.merge_lang);
    if (!opt.merge_plot.empty()) {
        check_plot(whole, opt.merge_plot);
        AtomicFile probe(opt.merge_plot, &outputs);
    }
    std::optional<MapCollector> maps;
    if (!opt.merge_plot.empty()) maps.emplace(whole);
    std::size_t rows = 0;
    try {
        rows = merge_sweep_parts(whole, out, parts, [&](std::size_t, const std::string& row) {
            if (maps) maps->add(row);
        }, &outputs);
    } catch (const InputError& e) {
        // The merged file is OUT.csv, the first of the files, not --out.
        if (e.key() != Key::out) throw;
        throw InputError(fmt::format("{} is not allowed: {}", e.value(), e.allowed()));
    }
    run.wrote(opt.merge_quiet, "wrote {}: {} from {}", out, count_of(static_cast<long long>(rows), "row"),
           count_of(static_cast<long long>(parts.size()), "file"));
    if (maps) write_plot(opt.merge_plot, *maps, print, language, opt.merge_quiet, run);
    return 0;
}

// More workers than scenarios, or than a few per core, only wait (and each is a thread: 100000
// of them ran for ten minutes without a row).
constexpr int kWorkersPerCore = 4;

// How many workers the sweep runs on: --workers, capped at the scenarios of this run and at
// kWorkersPerCore a core, with a note when the cap takes some away; else 0 (the tool's pool).
int sweep_workers(const std::optional<int>& asked, std::size_t scenarios, bool quiet) {
    if (!asked) return 0;
    if (*asked < 1) throw InputError(Key::workers, std::to_string(*asked), "at least 1");
    const int cores = dragon::cores();
    const int most = static_cast<int>(std::min<std::size_t>(std::max<std::size_t>(scenarios, 1),
                                                            static_cast<std::size_t>(kWorkersPerCore * cores)));
    const int workers = std::min(*asked, most);
    if (workers < *asked && !quiet)
        fmt::print(stderr, "dragon: note: --workers {}: {} run at once (at most one per scenario, {} here, and {} per "
                           "core, {} here)\n", *asked, workers, scenarios, kWorkersPerCore, kWorkersPerCore * cores);
    return workers;
}

int run_sweep(SweepOptions& opt, ToolRun& run) {
    if (opt.merge->parsed()) return run_merge(opt, run);
    RunOutputs& outputs = run.outputs;
    if (opt.workers && *opt.workers < 1) throw InputError(Key::workers, std::to_string(*opt.workers), "at least 1");
    const SweepSetup setup = make_setup(opt.request, opt.scenario, &outputs);
    const int workers = sweep_workers(opt.workers, setup.shard.size(setup.grid.size()), opt.quiet);
    std::optional<ThreadPool> own_pool;  // --workers: a pool of that size for this sweep
    if (workers > 0) own_pool.emplace(workers);
    Executor& ex = own_pool ? static_cast<Executor&>(*own_pool) : run.executor;
    opt.output.outputs = &outputs;  // the rows and the plot are this run's outputs
    check_sweep_output(opt.output);
    const std::optional<PrintSize> print = plot_print(opt.print, opt.plot);
    const Language language = parse_language(opt.lang);
    if (!opt.plot.empty()) {
        check_plot(setup, opt.plot);
        AtomicFile probe(opt.plot, &outputs);
    }
    // The map's values only when a map is asked for: a row is otherwise never held.
    std::optional<MapCollector> maps;
    if (!opt.plot.empty()) maps.emplace(setup);
    const bool to_stdout = opt.output.out.empty();
    if (to_stdout && !opt.json) {
        fmt::print("{}\n{}\n", spec_line(setup), csv_line(header(setup)));
        std::fflush(stdout);
    }
    ProgressLine progress("scenarios", opt.quiet);
    SweepCallbacks heard;
    heard.on_row = [&](std::size_t, const std::string& row) {
        if (maps) maps->add(row);
    };
    heard.on_made = [&](const SweepRow& row) {
        if (to_stdout && !opt.json) fmt::print("{}\n", row.csv);
        if (opt.json) print_json(row.json);
        if (to_stdout || opt.json) require_stdout_written();  // each row out as it finishes
    };
    heard.on_note = [&](const std::string& note) { status(opt.quiet, "{}", note); };
    heard.progress = [&](std::int64_t made, std::int64_t total) { progress.update(made, total); };
    const SweepTally t = write_sweep(setup, opt.output, ex, heard);
    if (!to_stdout)
        run.wrote(opt.quiet, "wrote {}: {}{}", opt.output.out, count_of(static_cast<long long>(t.done_before + t.made), "row"),
               t.done_before ? fmt::format(" ({} new)", t.made) : "");
    if (maps) write_plot(opt.plot, *maps, print, language, opt.quiet, run);
    // A run that fails leaves no finished file: the rows stay in the partial one, and --resume
    // makes the failed rows again.
    if (t.failed > 0)
        throw std::runtime_error(fmt::format(
            "{} of {} failed ({} status says why){}", t.failed, count_of(static_cast<long long>(t.made), "scenario"),
            t.failed == 1 ? "its row's" : "their rows'",
            opt.output.out.empty() ? ""
                                   : fmt::format("; the rows stay in {}, and --resume makes the failed ones again",
                                                 partial_path(opt.output.out))));
    return 0;
}

}  // namespace

void register_sweep(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<SweepOptions>();
    CLI::App* sub = app.add_subcommand(
        "sweep", "Maps the answers over the design space: a row per scenario, a column per answer; merge joins its parts");
    sub->add_option("file", opt->request.file, "Sweep file (TOML; see assets/sweeps/); flags override it");
    sub->add_option("--vary", opt->request.vary,
                    "NAME=FROM:TO:COUNT or NAME=V1,V2,...: a scenario value and its values (repeat for more; the first "
                    "varies slowest). NAME is a scenario flag: pitch, speed, bench-count, head-length, body-length, "
                    "width, hole-offset, start-turn, turn-radius, turn-pitch, arc-ratio")
        ->allow_extra_args(false);  // one spec per --vary: a sweep file after it is not a second one
    sub->add_option("--measure", opt->request.measures,
                    "What to answer per scenario: collide, min-pitch, turnaround, max-speed (a comma list)")
        ->delimiter(',')
        ->allow_extra_args(false);
    opt->scenario.add_to(sub, ScenarioUse::both_paths("no measure of this sweep reads it"), reg);
    sub->add_option("--lo", opt->request.lo, "min-pitch: smallest pitch searched, m, width+X, or auto (default: each scenario's own, as min-pitch searches it)");
    sub->add_option("--hi", opt->request.hi, "min-pitch: largest pitch searched, m, width+X, or auto (default: each scenario's own)");
    sub->add_option("--grid", opt->request.grid, "min-pitch: pitch spacing of the first scan, m (default 0.0025)");
    sub->add_option("--limit", opt->request.limit, "max-speed: handle speed limit, m/s (default 2)");
    sub->add_option("--from", opt->request.from,
                    "collide, turnaround, max-speed: window start, as their --from (a time, s, or head travel: -100m)")
        ->type_name("T|Xm");
    sub->add_option("--to", opt->request.to,
                    "collide, turnaround, max-speed: window end, as their --to (a time, s, or head travel: 100m)")
        ->type_name("T|Xm");
    sub->add_option("-o,--out", opt->output.out,
                    "Rows to this .csv, each made durable as it finishes (into OUT.csv.partial, renamed when all are "
                    "there); without it, onto stdout");
    sub->add_flag("--resume", opt->output.resume, "Go on with the rows -o already holds; compute only the rest");
    sub->add_flag("--json", opt->json, "Each row as one JSON object on stdout, one a line, as it finishes");
    sub->add_option("--shard", opt->request.shard, "K/N: run only the K-th of N disjoint parts (merge them after)");
    sub->add_option("--plot", opt->plot, "Also draw the map (.png, .svg or .pdf): line plots over one varied value, heat "
                                         "maps over two");
    opt->print.add_to(sub);
    add_language_flag(sub, opt->lang);
    sub->add_option("--workers", opt->workers,
                    fmt::format("Scenarios run at once (default: one per core; at most one per scenario and {} per "
                                "core: more would only wait)", kWorkersPerCore));
    add_quiet_flag(sub, opt->quiet);

    opt->merge = sub->add_subcommand("merge", "Joins a sweep's parts (its shards) into one file, checking every scenario "
                                              "is there once: dragon sweep merge OUT.csv PART.csv...");
    opt->merge->add_option("files", opt->merge_files, "OUT.csv, then the parts");
    opt->merge->allow_extras();  // named by run_merge, as the command line names a command's leftovers
    opt->merge->add_option("--plot", opt->merge_plot, "Also draw the map (.png, .svg or .pdf)");
    opt->merge_print.add_to(opt->merge);
    add_language_flag(opt->merge, opt->merge_lang);
    add_quiet_flag(opt->merge, opt->merge_quiet);
    reg.runners["sweep"] = [opt](ToolRun& run) { return run_sweep(*opt, run); };
}

}  // namespace dragon::cli
