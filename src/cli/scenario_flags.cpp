#include "scenario_flags.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>

#include <fmt/format.h>

#include "status.hpp"
#include "dragon/input_file.hpp"
#include "dragon/input_files.hpp"

namespace dragon::cli {

namespace {

struct FlagInfo {
    const char* name;
    ScenarioValues value;
    const char* help;
};

// Every scenario flag, the value it sets, its help line.
constexpr FlagInfo kFlags[] = {
    {"--pitch", value::pitch, "Coil-in spiral pitch, m (default 0.55)"},
    {"--speed", value::head_speed, "Head speed, m/s (default 1)"},
    {"--bench-count", value::bench_count, "Benches in the chain, head and tail included (default 223)"},
    {"--head-length", value::head_length, "Head board length, m (default 3.41)"},
    {"--body-length", value::body_length, "Body and tail board length, m (default 2.20)"},
    {"--width", value::width, "Board width, m (default 0.30)"},
    {"--hole-offset", value::hole_offset, "Hole centre to the nearer board end, m (default 0.275)"},
    {"--start-turn", value::start_turn, "Turn of the spiral the head starts on (default 16)"},
    {"--turn-radius", value::turn_radius, "Radius of the turning space, m (default 4.5)"},
    {"--turn-pitch", value::turn_pitch, "Pitch of the turnaround path's spirals, m (default 1.7)"},
    {"--arc-ratio", value::arc_ratio, "First S-curve arc radius over the second's (default 2)"},
};

const char* path_name(PathKind k) { return k == PathKind::spiral ? "plain spiral" : "turnaround path"; }

}  // namespace

ScenarioUse ScenarioUse::either_path() {
    return {values_read(PathKind::spiral), values_read(PathKind::turnaround), true, ""};
}

ScenarioUse ScenarioUse::drawing() {
    ScenarioUse u = either_path();
    u.on_spiral |= value::turn_radius;
    return u;
}

ScenarioUse ScenarioUse::pitch_search() {
    return {value::bench | value::head_speed | value::start_turn | value::turn_radius, 0, false,
            "it searches the pitch itself (--lo, --hi, --grid) on the plain spiral, up to the turning space"};
}

ScenarioUse ScenarioUse::turnaround_only() {
    return {0, values_read(PathKind::turnaround), false,
            "it runs on the turnaround path (--turn-pitch, --turn-radius and --arc-ratio shape it)"};
}

ScenarioUse ScenarioUse::both_paths(const char* why_not) {
    return {values_read(PathKind::spiral) | value::turn_radius, values_read(PathKind::turnaround), false, why_not};
}

void ScenarioFlags::add_to(CLI::App* sub, ScenarioUse use, Registry& reg) {
    use_ = use;
    reg.scenario_flags_unused[sub->get_name()] = use.why_not;
    sub->add_option("--scenario", file_, "Scenario TOML file (see assets/cumcm2024.toml); flags override it");
    if (use.path_choice) sub->add_option("--path", path_kind_, "Path: spiral (Q1-Q3, default) or turnaround (Q4-Q5)");
    for (const FlagInfo& f : kFlags) {
        if (!(use.all() & f.value)) continue;
        if (f.value == value::bench_count) sub->add_option(f.name, bench_count_, f.help);
        else sub->add_option(f.name, *slot(f.value), f.help);
    }
}

std::optional<double>* ScenarioFlags::slot(ScenarioValues v) {
    if (v == value::pitch) return &pitch_;
    if (v == value::head_speed) return &speed_;
    if (v == value::head_length) return &head_length_;
    if (v == value::body_length) return &body_length_;
    if (v == value::width) return &width_;
    if (v == value::hole_offset) return &hole_offset_;
    if (v == value::start_turn) return &start_turn_;
    if (v == value::turn_radius) return &turn_radius_;
    if (v == value::turn_pitch) return &turn_pitch_;
    if (v == value::arc_ratio) return &arc_ratio_;
    return nullptr;  // the bench count is a whole number, stored on its own
}

std::string ScenarioFlags::not_taken(const CLI::App& sub, const std::string& flag, const std::string& why) {
    if (flag == "--path" || flag == "--scenario" ||
        std::any_of(std::begin(kFlags), std::end(kFlags), [&](const FlagInfo& f) { return flag == f.name; })) {
        return fmt::format("dragon {} does not take {}{}{}", sub.get_name(), flag, why.empty() ? "" : ": ", why);
    }
    return "";
}

ScenarioValues ScenarioFlags::given() const {
    ScenarioValues v = bench_count_ ? value::bench_count : 0;
    for (const FlagInfo& f : kFlags)
        if (f.value != value::bench_count && slot(f.value)->has_value()) v |= f.value;
    return v;
}

void ScenarioFlags::fill(const std::string& scenario_file,
                         const std::vector<std::pair<std::string, std::string>>& values, const std::string& source) {
    if (file_.empty()) file_ = scenario_file;
    for (const auto& [name, text] : values) {
        // Named copy: clang 14 (the fuzz build) cannot capture a structured binding.
        const KeyInfo* key = find_toml_key(name);
        const std::string flag = key ? "--" + hyphenated(key->key) : std::string();
        const auto f = std::find_if(std::begin(kFlags), std::end(kFlags), [&](const FlagInfo& i) { return flag == i.name; });
        if (f == std::end(kFlags))
            throw InputError(fmt::format("{}: {} is not a scenario value", source, shown_text(name)));
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size())
            throw InputError(fmt::format("{}: {} = {} is not allowed: give a number", source, name, shown_text(text)));
        if (f->value == value::bench_count) {
            if (v != std::floor(v) || !(std::abs(v) <= 1e9))
                throw InputError(fmt::format("{}: bench_count = {} is not allowed: give a whole number", source,
                                             shown_text(text)));
            if (!bench_count_) bench_count_ = static_cast<long long>(v);
            continue;
        }
        if (std::optional<double>* s = slot(f->value); !*s) *s = v;
    }
}

Scenario ScenarioFlags::resolve(RunOutputs* outputs) const { return resolve(value::all, "", outputs); }

Scenario ScenarioFlags::resolve(ScenarioValues reads, const std::string& why, RunOutputs* outputs) const {
    Scenario s;
    ScenarioValues from_file = 0, from_flags = 0;
    if (!file_.empty()) {
        LoadedScenario loaded = read_scenario_file(file_, s, outputs);
        if (!warned_) print_warnings(loaded.warnings);
        warned_ = true;
        s = loaded.scenario;
        from_file = loaded.values;
    }
    if (!path_kind_.empty()) {
        if (path_kind_ == "spiral") s.path.kind = PathKind::spiral;
        else if (path_kind_ == "turnaround") s.path.kind = PathKind::turnaround;
        else throw InputError(fmt::format("--path {} is not allowed: use spiral or turnaround", path_kind_));
    }
    // The path this command runs on: its own when it has only one, the spiral first when both.
    if (!use_.path_choice) s.path.kind = use_.on_spiral ? PathKind::spiral : PathKind::turnaround;
    if (bench_count_) {
        if (*bench_count_ < 1 || *bench_count_ > 1000000)
            throw InputError(fmt::format("--bench-count {} is not allowed: the chain needs 1 to 1000000 benches",
                                         *bench_count_));
        s.bench.bench_count = static_cast<int>(*bench_count_);
        from_flags |= value::bench_count;
    }
    const auto set = [&from_flags](const std::optional<double>& flag, double& dst, ScenarioValues v) {
        if (!flag) return;
        dst = *flag;
        from_flags |= v;
    };
    set(pitch_, s.path.pitch, value::pitch);
    set(speed_, s.head_speed, value::head_speed);
    set(head_length_, s.bench.head_length, value::head_length);
    set(body_length_, s.bench.body_length, value::body_length);
    set(width_, s.bench.width, value::width);
    set(hole_offset_, s.bench.hole_offset, value::hole_offset);
    set(start_turn_, s.path.start_turn, value::start_turn);
    set(turn_radius_, s.path.turn_radius, value::turn_radius);
    set(turn_pitch_, s.path.turn_pitch, value::turn_pitch);
    set(arc_ratio_, s.path.arc_ratio, value::arc_ratio);

    const ScenarioValues on_path =
        use_.path_choice ? (s.path.kind == PathKind::spiral ? use_.on_spiral : use_.on_turnaround) : use_.all();
    const ScenarioValues used = on_path & reads;
    // A flag that this run does not read would silently do nothing: say so.
    for (const FlagInfo& f : kFlags) {
        if (!(from_flags & f.value) || (used & f.value)) continue;
        const PathKind other = s.path.kind == PathKind::spiral ? PathKind::turnaround : PathKind::spiral;
        if (!(on_path & f.value))
            throw InputError(fmt::format("{} is not used on the {}: add --path {} to use it, or leave it out",
                                         f.name, path_name(s.path.kind), to_string(other)));
        throw InputError(fmt::format("{} is not used: {}", f.name, why));
    }
    try {
        validate(s, used);
    } catch (const ScenarioError& e) {
        // A bad value that came from the file (and no flag overrode): name the file.
        if (e.values & from_file & ~from_flags)
            throw InputError(fmt::format("scenario file '{}': {}", file_, e.what()));
        throw;
    }
    return s;
}

}  // namespace dragon::cli
