#include "sweep_setup.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "status.hpp"
#include "window_flags.hpp"
#include "dragon/input_file.hpp"
#include "dragon/input_files.hpp"

namespace dragon::cli {

namespace {

// The file's [measure] options under the flags: a flag given wins. Each is checked as the flag
// would be, and named by its key.
void take_file_options(const SweepFile& f, const std::string& path, SweepRequest& req,
                       const std::vector<const MeasureInfo*>& measures) {
    MeasureOptions from_file;
    for (const SweepFile::Option& o : f.options) {
        const std::string where = fmt::format("sweep file '{}': [{}] {}", shown_text(path, 4096), shown_text(o.measure),
                                              shown_text(o.key));
        const auto number = [&] {
            char* end = nullptr;
            const double v = std::strtod(o.value.c_str(), &end);
            if (o.value.empty() || end != o.value.c_str() + o.value.size())
                throw InputError(fmt::format("{} = {} is not allowed: give a number", where, shown_text(o.value)));
            return v;
        };
        if (o.measure == "min-pitch" && o.key == "lo") {
            from_file.lo = parse_pitch_bound(where + " =", o.value, false);
            req.lo = req.lo.value_or(o.value);
        } else if (o.measure == "min-pitch" && o.key == "hi") {
            from_file.hi = parse_pitch_bound(where + " =", o.value, true);
            req.hi = req.hi.value_or(o.value);
        } else if (o.measure == "min-pitch" && o.key == "grid") {
            from_file.grid = number();
            if (const auto why = grid_problem(from_file.grid))
                throw InputError(fmt::format("{} = {} is not allowed: {}", where, shown_text(o.value), *why));
            req.grid = req.grid.value_or(from_file.grid);
        } else if (o.measure == "max-speed" && o.key == "limit") {
            from_file.limit = number();
            if (const auto why = limit_problem(from_file.limit))
                throw InputError(fmt::format("{} = {} is not allowed: {}", where, shown_text(o.value), *why));
            req.limit = req.limit.value_or(from_file.limit);
        } else if (o.measure == "window" && o.key == "from") {
            from_file.from = parse_along(where + " =", o.value);
            req.from = req.from.value_or(o.value);
        } else if (o.measure == "window" && o.key == "to") {
            from_file.to = parse_along(where + " =", o.value);
            req.to = req.to.value_or(o.value);
        } else {
            throw InputError(fmt::format("{} is not an option a sweep takes ([min-pitch] lo, hi, grid; [max-speed] "
                                         "limit; [window] from, to)", where));
        }
    }
    // The file's own values, each as the file gives it (a flag over one does not excuse it).
    check_options(from_file, measures, [&](const char* option) {
        const std::string measure = std::string(option) == "limit" ? "max-speed" : "min-pitch";
        return fmt::format("sweep file '{}': [{}] {} =", shown_text(path, 4096), measure, option);
    });
}

}  // namespace

SweepSetup make_setup(const SweepRequest& request, ScenarioFlags& flags, RunOutputs* outputs) {
    SweepRequest req = request;
    if (!req.file.empty()) {
        const SweepFile f = read_sweep_file(req.file, outputs);
        print_warnings(f.warnings);
        // An axis of the command line replaces the file's of the same name; the others follow it.
        std::vector<std::string> vary;
        for (const std::string& v : f.vary) {
            const std::string name = v.substr(0, v.find('='));
            if (std::none_of(req.vary.begin(), req.vary.end(), [&](const std::string& c) { return c.substr(0, c.find('=')) == name; }))
                vary.push_back(v);
        }
        vary.insert(vary.end(), req.vary.begin(), req.vary.end());
        req.vary = vary;
        if (req.measures.empty()) req.measures = f.measures;
        std::vector<const MeasureInfo*> all_measures;
        for (const MeasureInfo& m : sweep_measures()) all_measures.push_back(&m);
        take_file_options(f, req.file, req, all_measures);
        flags.fill(f.scenario, f.fixed, fmt::format("sweep file '{}': [fixed]", req.file));
    }
    const SweepAsked asked{req.vary, req.measures, req.lo,   req.hi, req.grid,
                           req.limit, req.from,     req.to, req.shard, flags.given()};
    const SweepWords words{[](const char* option) { return fmt::format("--{}", option); },
                           [](const char* value) { return fmt::format("--{}", value); }};
    return make_sweep_setup(asked, words, [&](ScenarioValues fixed, const std::string& why) {
        return flags.resolve(fixed, why, outputs);
    });
}

}  // namespace dragon::cli
