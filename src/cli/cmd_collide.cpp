// dragon collide (Q2): the first moment two benches touch.
#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/contact_search.hpp"
#include "cli/report.hpp"
#include "cli/scenario_flags.hpp"
#include "cli/status.hpp"
#include "dragon/analyses.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/tables.hpp"

namespace dragon::cli {

namespace {
struct CollideOptions {
    ScenarioFlags scenario;
    double from = 0.0;
    std::optional<double> to;
    bool json = false;
    std::string out;
    std::optional<int> digits;
    bool quiet = false;
};
}  // namespace

void register_collide(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<CollideOptions>();
    CLI::App* sub = app.add_subcommand("collide", "Q2: the first moment two benches touch, to 1e-9 s");
    opt->scenario.add_to(sub, ScenarioUse::either_path());
    sub->add_option("--from", opt->from, "Search from this time, s (default 0)");
    sub->add_option("--to", opt->to, "Search up to this time, s (default: until the head reaches the centre)");
    sub->add_flag("--json", opt->json, "Print one JSON object on stdout");
    sub->add_option("-o,--out", opt->out, "Also write the moment's handles (.xlsx: result2 layout, .csv, .json)");
    sub->add_option("--digits", opt->digits, "Decimals of x, y and speed in a .csv or .json -o, 0 to 17 (default 6)");
    add_quiet_flag(sub, opt->quiet);
    reg["collide"] = [opt]() {
        const std::string ext = extension_of(opt->out);
        if (opt->digits && ext != ".csv" && ext != ".json")
            throw InputError(fmt::format("--digits {} is not allowed {}: it sets the decimals of a .csv or .json -o",
                                         *opt->digits, opt->out.empty() ? "without -o" : "with " + ext));
        const int digits = checked_digits(opt->digits);
        const Scenario s = opt->scenario.resolve();
        const Simulation sim(s);
        double to = opt->to.value_or(sim.end_time());
        if (!std::isfinite(to))
            throw InputError("--to is needed on the turnaround path (it has no end)");
        if (!opt->out.empty()) AtomicFile probe(opt->out);
        const std::optional<Contact> c = first_contact_after(sim, opt->from, to);
        if (!c) {
            if (opt->json)
                fmt::print("{{\"time\": null, \"benches\": null, \"head_radius\": null, \"from\": {}, \"to\": {}}}\n",
                           json_number(opt->from), json_number(to));
            else
                fmt::print("no collision between t = {} s and t = {} s\n", format_time(opt->from), format_time(to));
            return 0;
        }
        if (!opt->out.empty()) {
            if (extension_of(opt->out) == ".xlsx") write_result2_xlsx(c->frame, opt->out);
            else write_table({c->frame}, opt->out, digits);
            status(opt->quiet, "wrote {}", opt->out);
        }
        if (opt->json) {
            fmt::print("{{\"time\": {}, \"benches\": [{}, {}], \"head_radius\": {}, \"point\": [{}, {}], "
                       "\"tolerance\": {}, \"evaluations\": {}, \"handles\": {}}}\n",
                       json_number(c->time), c->bench_a, c->bench_b, json_number(c->head_radius),
                       json_number(c->point.x), json_number(c->point.y), json_number(c->tolerance), c->steps,
                       handles_json(c->frame));
        } else {
            fmt::print("first contact at t = {} s: bench {} touches bench {}; head radius {:.6f} m\n",
                       format_resolved(c->time, c->tolerance), c->bench_a, c->bench_b, c->head_radius);
            print_single_frame(fmt::format("handles at t = {} s", format_resolved(c->time, c->tolerance)), c->frame);
        }
        return 0;
    };
}

}  // namespace dragon::cli
