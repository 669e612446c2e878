// dragon collide (Q2): the first moment two benches touch.
#include <cmath>

#include <fmt/format.h>

#include "dragon/answers.hpp"
#include "commands.hpp"
#include "wording.hpp"
#include "report.hpp"
#include "scenario_flags.hpp"
#include "status.hpp"
#include "window_flags.hpp"
#include "dragon/analyses.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/tables.hpp"

namespace dragon::cli {

namespace {
struct CollideOptions {
    ScenarioFlags scenario;
    WindowFlags window;
    bool json = false;
    std::string out;
    std::optional<int> digits;
    bool quiet = false;
    bool prove = false;
};

// With no contact the output file still answers: the table with its header and no rows, so
// that an older file from another run is never left looking like this one's answer.
void write_no_contact(const std::string& path, RunOutputs& outputs) {
    if (extension_of(path) == ".xlsx") write_result2_xlsx(Frame{}, path, kWorkbooks, &outputs);
    else write_table({}, path, kDefaultDigits, {}, &outputs);
}
}  // namespace

void register_collide(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<CollideOptions>();
    CLI::App* sub = app.add_subcommand("collide", "Q2: the first moment two benches touch, to 1e-9 s");
    opt->scenario.add_to(sub, ScenarioUse::either_path(), reg);
    opt->window.add_to(sub, "Search from here (default: 0 on the spiral, -100m on the turnaround path)",
                       "Search up to here (default: on the spiral as far as the dragon can follow it, its centre "
                       "or the end of its valid motion; 100m on the turnaround path)");
    sub->add_flag("--json", opt->json, "Print one JSON object on stdout");
    sub->add_flag("--prove", opt->prove,
                  "Prove every step of the search contact-free by enclosing each bench over it (slower; "
                  "without it each step rests on its rate bound checked at its end)");
    sub->add_option("-o,--out", opt->out,
                    "Also write the moment's handles (.xlsx: result2 layout, .csv, .json); with no contact, "
                    "the table's header and no rows");
    sub->add_option("--digits", opt->digits, "Decimals of every number of a .csv or .json -o (t without trailing zeros), 0 to 17 (default 6)");
    add_quiet_flag(sub, opt->quiet);
    reg.runners["collide"] = [opt](ToolRun& run) {
        Executor& ex = run.executor;
        RunOutputs& outputs = run.outputs;
        const std::string ext = extension_of(opt->out);
        if (opt->digits && ext != ".csv" && ext != ".json")
            throw InputError(fmt::format("--digits {} is not allowed {}: it sets the decimals of a .csv or .json -o",
                                         *opt->digits, opt->out.empty() ? "without -o" : "with " + ext));
        const int digits = checked_digits(opt->digits);
        const Scenario s = opt->scenario.resolve(&outputs);
        const RunWindow window = opt->window.resolve(default_window(s.path.kind));
        if (!opt->out.empty()) {
            if (ext != ".csv" && ext != ".json" && ext != ".xlsx")
                throw InputError(fmt::format("--out {} has extension '{}': use .csv, .json or .xlsx", opt->out, ext));
            AtomicFile probe(opt->out, &outputs);  // fail on an unwritable path before any work
        }
        const Simulation sim(s);
        ContactSearchOptions options;
        options.prove_steps = opt->prove;
        options.executor = &ex;
        const CollideAnswer search = collide(sim, window, options);
        const std::optional<Contact>& c = search.contact;
        if (!c) {
            if (!opt->out.empty()) write_no_contact(opt->out, outputs);
            if (opt->json) {
                print_json(collide_answer(search, true));
            } else {
                fmt::print("no collision between t = {} s and t = {} s (head travel {} m to {} m)\n",
                           format_time(search.window.from),
                           search.jam ? format_resolved(search.window.to, search.jam->tolerance)
                                      : format_time(search.window.to),
                           format_time(search.window.from_travel), format_time(search.window.to_travel));
                fmt::print("{}", window_cuts(search.window, "the search"));
                fmt::print("{}", proof_words(search.proof, nullptr));
            }
            if (!opt->out.empty()) run.wrote(opt->quiet, "no contact: wrote {} with the table's header and no rows", opt->out);
            return 0;
        }
        if (!opt->out.empty()) {
            if (extension_of(opt->out) == ".xlsx") write_result2_xlsx(c->frame, opt->out, kWorkbooks, &outputs);
            else write_table({c->frame}, opt->out, digits, {}, &outputs);
            run.wrote(opt->quiet, "wrote {}", opt->out);
        }
        if (opt->json) {
            print_json(collide_answer(search, true));
        } else if (search.overlap) {
            // The chain collided before the window: the verdict, and the benches where it starts.
            fmt::print("the chain collides before the search starts: {}{}\n", overlap_sentence(*search.overlap, search.asked.from),
                       search.asked.from.value > 0.0 ? " (an earlier --from finds it)" : "");
            print_single_frame(fmt::format("handles at t = {} s", format_time(c->time)), c->frame);
        } else {
            fmt::print("first contact at t = {} s (head travel {} m): bench {} touches bench {}; head radius {:.6f} m\n",
                       format_resolved(c->time, c->tolerance), format_resolved(c->travel, c->travel_tolerance),
                       c->bench_a, c->bench_b, c->head_radius);
            fmt::print("{}", proof_words(c->proof, &*c));
            print_single_frame(fmt::format("handles at t = {} s", format_resolved(c->time, c->tolerance)), c->frame);
        }
        return 0;
    };
}

}  // namespace dragon::cli
