// A sweep's setup, first line and rows (dragon/sweep_setup.hpp).
#include "dragon/sweep_setup.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dragon/shown_text.hpp"

namespace dragon {

namespace {

constexpr const char* kSpecPrefix = "# dragon sweep ";
constexpr int kFormat = 1;  // of the spec line and the rows; a later change of either raises it

}  // namespace

std::string measure_names(const std::vector<const MeasureInfo*>& measures) {
    std::vector<std::string> names;
    for (const MeasureInfo* m : measures) names.emplace_back(m->name);
    return fmt::format("{}", fmt::join(names, ", "));
}

bool has_measure(const std::vector<const MeasureInfo*>& measures, const char* name) {
    return std::any_of(measures.begin(), measures.end(), [&](const MeasureInfo* m) { return std::string(m->name) == name; });
}

// What min-pitch and max-speed refuse in an option whatever the scenario, in their words (the
// rules of min_pitch() and max_head_speed()): a sweep refuses it once, up front, rather than
// writing "refused" into every row. What depends on the scenario (a bound below its width)
// stays a row's refusal.
std::optional<std::string> limit_problem(double limit) {
    if (!std::isfinite(limit) || limit <= 0.0) return "it must be a finite speed > 0 m/s";
    return std::nullopt;
}
std::optional<std::string> grid_problem(double grid) {
    if (!(grid > 0.0) || !std::isfinite(grid)) return "give a pitch spacing above 0, in m";
    return std::nullopt;
}
constexpr double kMaxPitch = 1e3;  // m, the largest pitch a scenario takes

// The options of the measures, checked: `name` words each (a flag, or a sweep file's key).
void check_options(const MeasureOptions& o, const std::vector<const MeasureInfo*>& measures,
                   const std::function<std::string(const char* option)>& name) {
    if (has_measure(measures, "max-speed"))
        if (const auto why = limit_problem(o.limit))
            throw InputError(fmt::format("{} {} is not allowed: {}", name("limit"), error_value(o.limit), *why));
    if (!has_measure(measures, "min-pitch")) return;
    if (const auto why = grid_problem(o.grid))
        throw InputError(fmt::format("{} {} is not allowed: {}", name("grid"), error_value(o.grid), *why));
    for (const auto& [bound, option] : {std::pair{&o.lo, "lo"}, std::pair{&o.hi, "hi"}})
        if (!bound->above_width && !bound->automatic && !(bound->offset <= kMaxPitch))
            throw InputError(fmt::format("{} {} is not allowed: a pitch is at most {} m", name(option),
                                         error_value(bound->offset), kMaxPitch));
    if (!o.lo.above_width && !o.hi.above_width && !o.lo.automatic && !o.hi.automatic) {
        if (!(o.hi.offset > o.lo.offset))
            throw InputError(fmt::format("{} {} is not allowed with {} {}: the search needs lo < hi", name("hi"),
                                         error_value(o.hi.offset), name("lo"), error_value(o.lo.offset)));
        const double steps = std::ceil((o.hi.offset - o.lo.offset) / o.grid * (1.0 - 1e-12));
        if (steps > kMaxPitchGridSteps)
            throw InputError(fmt::format("{} {} is not allowed: it makes {:.3g} grid steps over [{}, {}]; at most {}",
                                         name("grid"), error_value(o.grid), steps, o.lo.offset, o.hi.offset,
                                         kMaxPitchGridSteps));
    }
}

SweepSetup make_sweep_setup(const SweepAsked& asked, const SweepWords& words,
                            const std::function<Scenario(ScenarioValues fixed, const std::string& why)>& base) {
    const auto option = [&](const char* o) { return words.option(o); };
    if (asked.vary.empty()) throw InputError(fmt::format("a sweep needs at least one {} NAME=VALUES", option("vary")));
    std::vector<Axis> axes;
    for (const std::string& v : asked.vary) axes.push_back(parse_axis(v));
    SweepGrid grid(std::move(axes));
    if (asked.measures.empty())
        throw InputError(fmt::format("a sweep needs {}: one or more of collide, min-pitch, turnaround, max-speed",
                                     option("measure")));
    std::vector<const MeasureInfo*> measures;
    for (const std::string& name : asked.measures) {
        const MeasureInfo& m = find_measure(name);
        if (has_measure(measures, m.name))
            throw InputError(fmt::format("{} {} is given twice: measure each once", option("measure"), name));
        measures.push_back(&m);
    }
    ScenarioValues reads = 0;
    for (const MeasureInfo* m : measures) {
        reads |= m->reads;
        for (const Axis& a : grid.axes())
            if (!(m->reads & a.parameter->value))
                throw InputError(fmt::format("{} {} is not allowed with {} {}: {} does not read the {} (every row would "
                                             "repeat one answer); measure it in a sweep of its own", option("vary"),
                                             a.parameter->name, option("measure"), m->name, m->name,
                                             a.parameter->quantity));
    }
    const auto only_for = [&](const std::optional<std::string>& given, const char* name, const char* measure) {
        if (given && !has_measure(measures, measure))
            throw InputError(fmt::format("{} {} is not allowed: it is an option of {}, which this sweep does not measure",
                                         option(name), *given, measure));
    };
    only_for(asked.lo, "lo", "min-pitch");
    only_for(asked.hi, "hi", "min-pitch");
    only_for(asked.grid ? std::optional<std::string>(fmt::format("{}", *asked.grid)) : std::nullopt, "grid", "min-pitch");
    only_for(asked.limit ? std::optional<std::string>(fmt::format("{}", *asked.limit)) : std::nullopt, "limit",
             "max-speed");
    const bool windowed =
        has_measure(measures, "collide") || has_measure(measures, "turnaround") || has_measure(measures, "max-speed");
    for (const auto& [given, name] : {std::pair{asked.from, "from"}, std::pair{asked.to, "to"}})
        if (given && !windowed)
            throw InputError(fmt::format("{} {} is not allowed: it sets the window of collide, turnaround and "
                                         "max-speed, and this sweep measures none of them", option(name), *given));
    for (const Axis& a : grid.axes())
        if (asked.fixed_given & a.parameter->value)
            throw InputError(fmt::format("{} is not allowed: the sweep varies it ({} {}=...); give it one way",
                                         words.value(a.parameter->name), option("vary"), a.parameter->name));
    const ScenarioValues fixed = reads & ~grid.varied();
    Scenario s = base(fixed, fmt::format("no measure of this sweep ({}) reads it", measure_names(measures)));
    s.path.kind = PathKind::spiral;
    MeasureOptions options;
    if (asked.lo) options.lo = parse_pitch_bound(option("lo"), *asked.lo, false);
    if (asked.hi) options.hi = parse_pitch_bound(option("hi"), *asked.hi, true);
    if (asked.grid) options.grid = *asked.grid;
    if (asked.limit) options.limit = *asked.limit;
    for (const auto& [given, name] : {std::pair{asked.from, "from"}, std::pair{asked.to, "to"}}) {
        if (!given) continue;
        const std::optional<Along> a = parse_along(*given);
        if (!a)
            throw InputError(fmt::format("{} {} is not allowed: give a time in seconds (12.5, or 12.5s) or a length of "
                                         "the head's travel in metres (-100m)", option(name), *given));
        (std::string(name) == "from" ? options.from : options.to) = a;
    }
    check_options(options, measures, option);
    return {std::move(grid), std::move(measures), s, fixed, options,
            parse_shard(asked.shard.empty() ? "1/1" : asked.shard)};
}

std::string spec_line(const SweepSetup& setup) {
    Json vary = Json::object();
    for (const Axis& a : setup.grid.axes()) vary[a.parameter->name] = a.cells;
    Json fixed = Json::object();
    for (const SweepParameter& p : sweep_parameters())
        if (setup.fixed & p.value)
            fixed[p.name] = p.whole ? Json(static_cast<long long>(get_parameter(setup.base, p))) : Json(get_parameter(setup.base, p));
    Json options = Json::object();
    if (has_measure(setup.measures, "min-pitch"))
        options["min-pitch"] = {{"lo", setup.options.lo.text()}, {"hi", setup.options.hi.text()}, {"grid", setup.options.grid}};
    if (has_measure(setup.measures, "max-speed")) options["max-speed"] = {{"limit", setup.options.limit}};
    Json window = Json::object();
    if (setup.options.from) window["from"] = to_string(*setup.options.from);
    if (setup.options.to) window["to"] = to_string(*setup.options.to);
    if (!window.empty()) options["window"] = window;
    Json measures = Json::array();
    for (const MeasureInfo* m : setup.measures) measures.push_back(m->name);
    const Json spec = {{"format", kFormat},
                       {"measure", measures},
                       {"vary", vary},
                       {"fixed", fixed},
                       {"options", options},
                       {"shard", fmt::format("{}/{}", setup.shard.index, setup.shard.count)}};
    return kSpecPrefix + spec.dump(-1, ' ', false, Json::error_handler_t::replace);
}

namespace {

Json parse_spec(const std::string& line, const std::string& file) {
    const auto bad = [&](const std::string& why) {
        return InputError(fmt::format("'{}' is not the rows of a dragon sweep: {}", file, why));
    };
    if (line.rfind(kSpecPrefix, 0) != 0) throw bad("its first line does not start with '# dragon sweep'");
    Json spec = Json::parse(line.substr(std::string(kSpecPrefix).size()), nullptr, false);
    if (spec.is_discarded() || !spec.is_object()) throw bad("its first line holds no sweep");
    if (spec.value("format", 0) != kFormat)
        throw bad(fmt::format("it was written in format {}, and this dragon reads format {}", spec.value("format", 0),
                              kFormat));
    return spec;
}

}  // namespace

SweepSetup read_spec_line(const std::string& line, const std::string& file) {
    const Json spec = parse_spec(line, file);
    try {
        std::vector<Axis> axes;
        for (const auto& [name, cells] : spec.at("vary").items()) axes.push_back(axis_from_cells(name, cells));
        std::vector<const MeasureInfo*> measures;
        for (const Json& m : spec.at("measure")) measures.push_back(&find_measure(m.get<std::string>()));
        Scenario base;
        ScenarioValues fixed = 0;
        for (const auto& [name, v] : spec.at("fixed").items()) {
            const SweepParameter* p = find_sweep_parameter(name);
            if (!p) throw InputError(fmt::format("unknown fixed value {}", name));
            set_parameter(base, *p, v.get<double>());
            fixed |= p->value;
        }
        MeasureOptions options;
        const Json& o = spec.at("options");
        if (o.contains("min-pitch")) {
            options.lo = parse_pitch_bound("lo", o["min-pitch"].at("lo").get<std::string>(), false);
            options.hi = parse_pitch_bound("hi", o["min-pitch"].at("hi").get<std::string>(), true);
            options.grid = o["min-pitch"].at("grid").get<double>();
        }
        if (o.contains("max-speed")) options.limit = o["max-speed"].at("limit").get<double>();
        if (o.contains("window")) {
            for (const char* end : {"from", "to"}) {
                if (!o["window"].contains(end)) continue;
                const std::optional<Along> a = parse_along(o["window"][end].get<std::string>());
                if (!a) throw InputError(fmt::format("its window's {} is not a time or a head travel", end));
                (std::string(end) == "from" ? options.from : options.to) = a;
            }
        }
        return {SweepGrid(std::move(axes)), std::move(measures), base, fixed, options,
                parse_shard(spec.at("shard").get<std::string>())};
    } catch (const InputError& e) {
        throw InputError(fmt::format("'{}' is not the rows of a dragon sweep: its first line: {}", file, e.what()));
    } catch (const Json::exception& e) {
        throw InputError(fmt::format("'{}' is not the rows of a dragon sweep: its first line: {}", file, e.what()));
    }
}

std::string spec_difference(const std::string& found, const std::string& expected) {
    if (found.rfind(kSpecPrefix, 0) != 0)
        return fmt::format("its first line '{}' is not what a sweep writes (# dragon sweep {{...}})", shown_text(found, 60));
    const Json a = Json::parse(found.substr(std::string(kSpecPrefix).size()), nullptr, false);
    const Json b = Json::parse(expected.substr(std::string(kSpecPrefix).size()), nullptr, false);
    if (a.is_discarded() || !a.is_object()) return "its first line holds no sweep (it is not JSON after '# dragon sweep')";
    const auto shown = [](const Json& v) { return shown_text(v.dump(-1, ' ', false, Json::error_handler_t::replace), 60); };
    for (const auto& [key, value] : b.items()) {
        if (!a.contains(key)) return fmt::format("its first line has no '{}'", key);
        if (a[key] == value) continue;
        // The axes one by one: which values differ is what the reader needs.
        if (key == "vary" && a[key].is_object())
            for (const auto& [name, cells] : value.items())
                if (!a[key].contains(name) || a[key][name] != cells)
                    return fmt::format("it varies {} {}, and this sweep {}", name,
                                       a[key].contains(name) ? "over " + shown(a[key][name]) : "not at all",
                                       "over " + shown(cells));
        return fmt::format("its first line's {} is {}, and this sweep's {}", key, shown(a[key]), shown(value));
    }
    for (const auto& [key, value] : a.items())
        if (!b.contains(key)) return fmt::format("its first line has '{}', which this sweep has not", key);
    return "its first line differs";
}

std::string whole_spec_line(const std::string& line, const std::string& file) {
    Json spec = parse_spec(line, file);
    spec["shard"] = "1/1";
    return kSpecPrefix + spec.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::vector<std::string> header(const SweepSetup& setup) {
    std::vector<std::string> h;
    for (const Axis& a : setup.grid.axes()) h.emplace_back(a.parameter->name);
    for (const MeasureInfo* m : setup.measures)
        for (const std::string& c : m->columns) h.push_back(std::string(m->name) + "." + c);
    h.emplace_back("status");
    return h;
}

SweepRow make_row(const SweepSetup& setup, std::size_t index) {
    const Scenario s = setup.grid.scenario(setup.base, index);
    std::vector<std::string> cells = setup.grid.cells(index);
    SweepRow row;
    row.json = Json::object();
    const std::vector<std::size_t> pos = setup.grid.position(index);
    for (std::size_t k = 0; k < setup.grid.axes().size(); ++k) {
        const Axis& a = setup.grid.axes()[k];
        const double v = a.values[pos[k]];
        row.json[a.parameter->name] = a.parameter->whole ? Json(static_cast<long long>(v)) : Json(v);
    }
    std::vector<std::string> notes;
    for (const MeasureInfo* m : setup.measures) {
        const MeasureResult r = run_measure(*m, s, setup.options);
        const std::vector<std::string> answer = r.answer ? flatten(*r.answer, m->columns)
                                                         : std::vector<std::string>(m->columns.size());
        cells.insert(cells.end(), answer.begin(), answer.end());
        row.json[m->name] = r.answer ? *r.answer : Json(nullptr);
        if (!r.note.empty()) notes.push_back(r.note);
        row.failed = row.failed || r.state == MeasureResult::State::failed;
    }
    const std::string status = notes.empty() ? "ok" : fmt::format("{}", fmt::join(notes, "; "));
    cells.push_back(status);
    row.json["status"] = status;
    row.csv = csv_line(cells);
    return row;
}

}  // namespace dragon
