// dragon min-pitch (Q3): the smallest pitch that reaches the turning space collision-free.
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "dragon/answers.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "report.hpp"
#include "scenario_flags.hpp"
#include "wording.hpp"
#include "status.hpp"
#include "dragon/analyses.hpp"
#include "dragon/contest.hpp"

namespace dragon::cli {

namespace {
// Where a lower --lo can still look for a minimum below the range, or why none can: --lo must
// stay above m.lowest, and a bracket within the tolerance of it leaves nothing to search.
std::string lower_lo_advice(const MinPitch& m) {
    const std::string why = m.lowest_is_start
                                ? fmt::format("at {} m the head would start on the turning space's edge", m.lowest)
                                : fmt::format("{} m is the bench width", m.lowest);
    if (m.search_lo - m.lowest <= m.tolerance) return fmt::format(", and there is no lower pitch to search: {}", why);
    return fmt::format(" (lower --lo to find it, keeping it above {} m: {})", m.lowest, why);
}

struct MinPitchOptions {
    ScenarioFlags scenario;
    std::optional<double> lo, hi;  // unset: the scenario's default range (pitch_search_range)
    double grid = kDefaultPitchGrid;
    bool json = false;
    bool prove = false;
    bool quiet = false;
};

}  // namespace

void register_min_pitch(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<MinPitchOptions>();
    CLI::App* sub = app.add_subcommand(
        "min-pitch", "Q3: the smallest pitch with which the head reaches the turning space collision-free");
    opt->scenario.add_to(sub, ScenarioUse::pitch_search(), reg);
    sub->add_option("--lo", opt->lo, "Smallest pitch searched, m (default 0.35, or just above the smallest "
                                     "pitch this dragon can use)");
    sub->add_option("--hi", opt->hi, "Largest pitch searched, m (default 0.55, or 1.5 times --lo's default)");
    sub->add_option("--grid", opt->grid,
                    "Pitch spacing of the first scan, m (default 0.0025); windows narrower than this may pass unseen");
    sub->add_flag("--prove", opt->prove,
                  "Prove every pitch of the collision-free intervals, not only the pitches run: enclose the benches "
                  "over cells of head radius and pitch (slower)");
    sub->add_flag("--json", opt->json, "Print one JSON object on stdout");
    add_quiet_flag(sub, opt->quiet);
    reg.runners["min-pitch"] = [opt](ToolRun& run) {
        Executor& ex = run.executor;
        RunOutputs& outputs = run.outputs;
        const Scenario s = opt->scenario.resolve(&outputs);
        const PitchRange range = pitch_search_range(s, opt->lo, opt->hi);
        // Said before it starts, terminal or not: a search many times the contest's takes minutes.
        if (const double steps = pitch_grid_steps(range.lo, range.hi, opt->grid);
            steps > kCostlyPitchGridSteps && steps <= kMaxPitchGridSteps && !opt->quiet)
            fmt::print(stderr, "dragon: note: {:.0f} pitches to scan over [{}, {}] m on a {} m grid, {:.0f} times the "
                               "contest's search: this may take minutes (a coarser --grid or a narrower --lo/--hi is "
                               "faster)\n", steps, range.lo, range.hi, opt->grid, steps / 80.0);
        const MinPitch m = [&] {
            ProgressLine progress("pitches", opt->quiet);  // erased before the answer is printed
            dragon::MinPitchOptions options;
            options.grid = opt->grid;
            options.executor = &ex;
            options.prove = opt->prove;
            options.progress = [&progress](std::int64_t done, std::int64_t total) { progress.update(done, total); };
            return min_pitch(s, range.lo, range.hi, options);
        }();
        if (opt->json) {
            print_json(min_pitch_answer(m, s.path.turn_radius));
            return 0;
        }
        // The pitch is resolved to tol::pitch (1e-9 m): ten decimals show it.
        if (m.below_range)
            fmt::print("the range's low end, {} m, already reaches radius {} m with no collision: the minimum "
                       "pitch lies at or below it{}\n", m.search_lo, s.path.turn_radius, lower_lo_advice(m));
        else if (m.above_range)
            fmt::print("no pitch in [{}, {}] m takes the head to radius {} m without a collision{}: the minimum "
                       "pitch, if there is one, lies above {} m (raise --hi to look for it)\n", m.search_lo, m.search_hi,
                       s.path.turn_radius, m.jam ? " and before its motion ends" : "", m.search_hi);
        else
            fmt::print("minimum pitch: {:.10f} m (head reaches radius {} m with no collision on the way)\n",
                       m.pitch, s.path.turn_radius);
        if (!range.moved.empty()) fmt::print("  searched {}..{} m: {}\n", m.search_lo, m.search_hi, range.moved);
        for (const PitchInterval& i : m.intervals)
            fmt::print("  [{:.10f}, {:.10f}] m  {}\n", i.lo, i.hi, i.feasible ? "collision-free" : "collides");
        if (m.jam)
            fmt::print("at pitch {} m (the largest of the scan where this happens) the dragon cannot follow the spiral "
                       "to radius {} m at all: {}\n", m.jam->pitch, s.path.turn_radius, jam_sentence(m.jam->jam));
        fmt::print("search: {}\n", min_pitch_guarantee(m));
        fmt::print("{}", pitch_proof_words(m));
        return 0;
    };
}

}  // namespace dragon::cli
