// dragon min-pitch (Q3): the smallest pitch that reaches the turning space collision-free.
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cli/report.hpp"
#include "cli/scenario_flags.hpp"
#include "cli/status.hpp"
#include "dragon/analyses.hpp"

namespace dragon::cli {

namespace {
struct MinPitchOptions {
    ScenarioFlags scenario;
    double lo = 0.35, hi = 0.55, grid = kDefaultPitchGrid;
    bool json = false;
    bool quiet = false;
};
}  // namespace

void register_min_pitch(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<MinPitchOptions>();
    CLI::App* sub = app.add_subcommand(
        "min-pitch", "Q3: the smallest pitch with which the head reaches the turning space collision-free");
    opt->scenario.add_to(sub, ScenarioUse::pitch_search());
    sub->add_option("--lo", opt->lo, "Smallest pitch searched, m (default 0.35)");
    sub->add_option("--hi", opt->hi, "Largest pitch searched, m (default 0.55)");
    sub->add_option("--grid", opt->grid,
                    "Pitch spacing of the first scan, m (default 0.0025); windows narrower than this may pass unseen");
    sub->add_flag("--json", opt->json, "Print one JSON object on stdout");
    add_quiet_flag(sub, opt->quiet);
    reg["min-pitch"] = [opt]() {
        const Scenario s = opt->scenario.resolve();
        const MinPitch m = [&] {
            ProgressLine progress("pitches", opt->quiet);  // erased before the answer is printed
            return min_pitch(s, opt->lo, opt->hi, opt->grid,
                             [&progress](std::int64_t done, std::int64_t total) { progress.update(done, total); });
        }();
        if (opt->json) {
            std::string iv;
            for (const PitchInterval& i : m.intervals)
                iv += fmt::format("{}{{\"lo\": {}, \"hi\": {}, \"feasible\": {}}}", iv.empty() ? "" : ", ",
                                  json_number(i.lo), json_number(i.hi), i.feasible ? "true" : "false");
            fmt::print("{{\"pitch\": {}, \"turn_radius\": {}, \"search\": [{}, {}], \"intervals\": [{}], "
                       "\"guarantee\": \"{}\"}}\n",
                       json_number(m.pitch), json_number(s.path.turn_radius), json_number(m.search_lo),
                       json_number(m.search_hi), iv, m.guarantee);
            return 0;
        }
        if (std::isnan(m.pitch))
            fmt::print("no pitch in [{}, {}] m reaches radius {} m without a collision\n", m.search_lo,
                       m.search_hi, s.path.turn_radius);
        else
            fmt::print("minimum pitch: {:.8f} m (head reaches radius {} m with no collision on the way)\n",
                       m.pitch, s.path.turn_radius);
        for (const PitchInterval& i : m.intervals)
            fmt::print("  [{:.8f}, {:.8f}] m  {}\n", i.lo, i.hi, i.feasible ? "collision-free" : "collides");
        fmt::print("search: {}\n", m.guarantee);
        return 0;
    };
}

}  // namespace dragon::cli
