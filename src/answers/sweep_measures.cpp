#include "dragon/sweep_measures.hpp"
#include "dragon/executor.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>

#include "dragon/answers.hpp"
#include "dragon/turnaround.hpp"

namespace dragon {

namespace {

// The chain already collides where collide's search starts: a verdict the row reports in place
// of an answer (run_measure).
struct CollidesAtStart {
    Overlap overlap;
    Along start;
};

const std::vector<std::string> kJamKeys = {"jam.time",  "jam.travel", "jam.handle",   "jam.kind",
                                           "jam.ahead", "jam.point",  "jam.tolerance"};

std::vector<std::string> with_jam(std::vector<std::string> keys, std::vector<std::string> after = {},
                                  std::vector<std::string> jam_extra = {}) {
    keys.insert(keys.end(), kJamKeys.begin(), kJamKeys.end());
    keys.insert(keys.end(), jam_extra.begin(), jam_extra.end());
    keys.insert(keys.end(), after.begin(), after.end());
    return keys;
}

// The answer without what its searches proved (its own "enclosure" and "proof", and its jam's):
// how a search went is not a value of the scenario, and a sweep's columns stay those its files
// were written with.
Json without_proofs(Json answer) {
    answer.erase("enclosure");
    answer.erase("proof");
    if (Json& j = answer["jam"]; j.is_object()) {
        j.erase("enclosure");
        j.erase("proof");
    }
    return answer;
}

std::string cell(const Json& v) {
    if (v.is_null()) return "";
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number_float() && !std::isfinite(v.get<double>())) return "";
    return json_text(v);
}

// Every leaf key of `v` under `prefix`: objects are walked, anything else (a null object too)
// is a leaf.
void leaves(const Json& v, const std::string& prefix, std::vector<std::string>& out) {
    if (!v.is_object()) {
        out.push_back(prefix);
        return;
    }
    for (const auto& [k, item] : v.items()) leaves(item, prefix.empty() ? k : prefix + "." + k, out);
}

// Each measure as its command runs it, on the calling thread: the sweep spreads the scenarios
// over the cores, and work nested inside one would only queue behind them. `jam` is set to
// where the end of the valid motion cut the analysis short.
Json collide_measure(const Scenario& s, const MeasureOptions& options, std::string& jam) {
    InlineExecutor here(options.stop_source);
    const CollideAnswer search = collide(Simulation(s), options.window(s.path.kind), &here);
    if (search.overlap) throw CollidesAtStart{*search.overlap, search.asked.from};
    if (search.jam) jam = "no contact before the end of the valid motion: " + jam_sentence(*search.jam);
    // The command's keys but what it proved and the overlap (always null here: an overlap is the
    // row's verdict instead).
    Json answer = collide_answer(search, false);
    answer.erase("overlap_at_start");
    return without_proofs(answer);
}

Json min_pitch_measure(const Scenario& s, const MeasureOptions& options, std::string& jam) {
    InlineExecutor here(options.stop_source);
    dragon::MinPitchOptions o;
    o.grid = options.grid;
    o.executor = &here;
    const MinPitch mp = min_pitch(s, options.lo.at(s), options.hi.at(s), o);
    if (mp.jam)
        jam = fmt::format("at pitch {} m the dragon cannot follow the spiral to radius {} m: {}", mp.jam->pitch,
                          s.path.turn_radius, jam_sentence(mp.jam->jam));
    return without_proofs(min_pitch_answer(mp, s.path.turn_radius));
}

// The command's design, followability and check for a first contact; its length study (two
// dozen other S-curves) is the command's to print, not a value of this scenario.
Json turnaround_measure(const Scenario& s, const MeasureOptions& options, std::string& jam) {
    InlineExecutor here(options.stop_source);
    const SCurve design = design_s_curve(s);
    const std::optional<Jam> design_jam = turnaround_jam(Simulation(s));
    const RunClearance clear = min_clearance(s, options.window(PathKind::turnaround), {}, &here);
    const std::optional<Jam>& j = clear.jam ? clear.jam : design_jam;
    if (j) jam = jam_sentence(*j);
    return without_proofs(turnaround_answer(design, design_jam, clear, nullptr));
}

Json max_speed_measure(const Scenario& s, const MeasureOptions& options, std::string& jam) {
    InlineExecutor here(options.stop_source);
    const MaxSpeed v = max_head_speed(s, options.limit, options.window(PathKind::turnaround), &here);
    if (v.jam)
        jam = v.unbounded ? fmt::format("no head speed keeps every handle at or under {} m/s: {}", options.limit,
                                        jam_sentence(*v.jam))
                          : "searched only as far as " + jam_sentence(*v.jam);
    // The command's keys but how the search went, as collide's.
    return without_proofs(max_speed_answer(v, options.limit));
}

}  // namespace

const std::vector<MeasureInfo>& sweep_measures() {
    static const std::vector<MeasureInfo> all = {
        {"collide", PathKind::spiral, values_read(PathKind::spiral), collide_measure,
         with_jam({"time", "travel", "benches", "head_radius", "point", "tolerance", "evaluations", "from", "to",
                   "from_travel", "to_travel"}), "time",
         "first contact", "s", true},
        {"min-pitch", PathKind::spiral, value::bench | value::head_speed | value::start_turn | value::turn_radius, min_pitch_measure,
         with_jam({"pitch", "below_range", "above_range", "turn_radius", "search", "grid", "intervals"}, {"guarantee"},
                  {"jam.pitch"}),
         "pitch", "minimum pitch", "m", false},
        {"turnaround", PathKind::turnaround, values_read(PathKind::turnaround), turnaround_measure,
         with_jam({"r1", "r2", "length", "ratio", "pitch", "entry_radius", "entry", "exit", "c1", "c2", "joint", "angle1",
                   "angle2", "length1", "length2", "max_radius", "followable", "first_contact.time",
                   "first_contact.travel", "first_contact.benches", "first_contact.head_radius", "first_contact.point",
                   "first_contact.tolerance", "clearance.distance", "clearance.at_least", "clearance.time",
                   "clearance.travel", "clearance.benches", "clearance.collision_free",
                   "clearance.evaluations", "clearance.from",
                   "clearance.to", "clearance.from_travel", "clearance.to_travel"}),
         "clearance.distance", "smallest clearance", "m", true},
        {"max-speed", PathKind::turnaround, values_read(PathKind::turnaround), max_speed_measure,
         with_jam({"max_head_speed", "ratio", "unbounded", "handle", "time", "travel", "tied", "head_arc", "limit",
                   "from", "to", "from_travel", "to_travel"},
                  {"scan_step", "scan_travel", "candidates", "evaluations"}),
         "max_head_speed", "largest head speed", "m/s", true},
    };
    return all;
}

const MeasureInfo& find_measure(const std::string& name) {
    for (const MeasureInfo& m : sweep_measures())
        if (name == m.name) return m;
    throw InputError(Key::measure, name.empty() ? "''" : name, "use collide, min-pitch, turnaround or max-speed");
}

RunWindow MeasureOptions::window(PathKind kind) const {
    RunWindow w = default_window(kind);
    if (from) w.from = *from;
    if (to) w.to = *to;
    return w;
}

double PitchBound::at(const Scenario& s) const {
    if (automatic) {
        const PitchRange r = default_pitch_range(s);
        return upper ? r.hi : r.lo;
    }
    if (!above_width) return offset;
    return std::strtod(fmt::format("{:.12g}", s.bench.width + offset).c_str(), nullptr);
}

std::string PitchBound::text() const {
    if (automatic) return "auto";
    return above_width ? fmt::format("width+{}", offset) : fmt::format("{}", offset);
}

PitchBound parse_pitch_bound(const std::string& flag, const std::string& text, bool upper) {
    if (text == "auto") return {0.0, false, true, upper};
    const bool relative = text.rfind("width+", 0) == 0;
    const std::string number = relative ? text.substr(6) : text;
    char* end = nullptr;
    const double v = std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(v) || (relative && v < 0.0))
        throw InputError(fmt::format("{} {} is not allowed: give a pitch in m (0.35), or the bench width plus one "
                                     "(width+0.05) when the sweep varies the width, or auto (each scenario's default range)", flag, text));
    return {v, relative, false, upper};
}

MeasureResult run_measure(const MeasureInfo& m, const Scenario& scenario, const MeasureOptions& options) {
    using State = MeasureResult::State;
    MeasureResult out;
    try {
        Scenario s = scenario;
        s.path.kind = m.path;
        validate(s, m.reads);
        std::string jam;
        out.answer = m.answer(s, options, jam);
        if (!jam.empty()) out.state = State::jam, out.note = fmt::format("jam ({}): {}", m.name, jam);
    } catch (const CollidesAtStart& c) {
        // The chain collides: a verdict on the scenario, as min-pitch gives it, not a refusal.
        out = {State::collides, std::nullopt, overlap_note_prefix(m) + overlap_sentence(c.overlap, c.start)};
    } catch (const InputError& e) {
        out = {State::refused, std::nullopt, fmt::format("refused ({}): {}", m.name, e.what())};
    } catch (const Cancelled&) {
        throw;  // the caller stopped the sweep: no row, not a failed one
    } catch (const std::exception& e) {
        // Not the scenario's fault: the row says so and the sweep goes on (the run fails at its end).
        out = {State::failed, std::nullopt, fmt::format("failed ({}): {}", m.name, e.what())};
    }
    return out;
}

std::string overlap_note_prefix(const MeasureInfo& m) { return fmt::format("collides at the start ({}): ", m.name); }

std::vector<std::string> flatten(const Json& answer, const std::vector<std::string>& columns) {
    std::vector<std::string> keys;
    leaves(answer, "", keys);
    for (const std::string& k : keys) {
        bool known = false;
        for (const std::string& c : columns) known = known || c == k || c.rfind(k + ".", 0) == 0;
        if (!known) throw std::logic_error("the answer's key '" + k + "' has no column in the sweep's rows");
    }
    std::vector<std::string> cells;
    for (const std::string& c : columns) {
        const Json* v = &answer;
        for (std::size_t from = 0; v && from <= c.size();) {
            const std::size_t dot = std::min(c.find('.', from), c.size());
            const std::string part = c.substr(from, dot - from);
            v = v->is_object() && v->contains(part) ? &(*v)[part] : nullptr;
            from = dot + 1;
        }
        cells.push_back(v ? cell(*v) : "");
    }
    return cells;
}

}  // namespace dragon
