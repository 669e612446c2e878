// A storyboard file read into data: [film] settings and [[shot]] tables, every key checked.
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "dragon/film.hpp"
#include "dragon/input_file.hpp"
#include "dragon/input_files.hpp"
#include "dragon/sweep.hpp"
#include "storyboard_values.hpp"

namespace dragon {

namespace {

// Where a storyboard's key is, and what is wrong with it, in one line. A `why` that says
// something of the key ("= 0 is not allowed: ...", "is not a key of a shot", "must be a
// string") has the key as its subject: "[film] fps = 0 is not allowed", "shot 2 (\"close\"):
// rate = -5 is not allowed"; a sentence of its own follows the key: "shot 1, key 'rate': give a
// rate ... or a duration".
std::string storyboard_message(const std::string& file, int shot, const std::string& shot_name, const std::string& key,
                               const std::string& why) {
    const bool predicate = why.rfind("= ", 0) == 0 || why.rfind("is ", 0) == 0 || why.rfind("must ", 0) == 0;
    if (shot == 0) return fmt::format("storyboard '{}', [film] {}{}{}", file, key, predicate ? " " : ": ", why);
    const std::string where = shot_name == fmt::format("shot {}", shot)
                                  ? fmt::format("storyboard '{}', shot {}", file, shot)
                                  : fmt::format("storyboard '{}', shot {} ({})", file, shot, shot_name);
    if (predicate) return fmt::format("{}: {} {}", where, key, why);
    return fmt::format("{}, key '{}': {}", where, key, why);
}

}  // namespace

StoryboardError::StoryboardError(const std::string& file, int shot_, const std::string& shot_name,
                                 const std::string& key_, const std::string& why)
    : InputError(storyboard_message(shown_text(file, 4096), shot_, shown_text(shot_name), key_, why)), shot(shot_),
      key(key_) {}

namespace {

using film::Where;

// A shot's key that sets a scenario value over its scenario file: the key table's name
// (pitch, speed, bench_count, ...), as a scenario file names it.
bool sets_scenario_value(const KeyInfo& k) { return k.scenario != 0; }

// A scene's keys: its scenario, the scenario's values, its window and what it shows.
std::set<std::string> view_keys() {
    std::set<std::string> keys = {"scenario", "path", "from", "to", "camera", "speed_colours", "guides", "label"};
    for (const KeyInfo& k : all_keys())
        if (sets_scenario_value(k)) keys.insert(std::string(k.name));
    return keys;
}

struct Context {
    std::string file, base_dir, asset_dir;
    std::string default_scenario;  // [film] scenario
    // Each scenario file read once, however many shots name it.
    std::map<std::string, Scenario> loaded;
    RunOutputs* outputs = nullptr;  // the run whose inputs the scenario files are, if any
    KeyWarnings warnings;  // the scenario files' old names, each file's once
};

// The scenario a name stands for: a preset of the asset folder, or a .toml file beside the
// storyboard. A bad one is named by `key` of `w`: the shot's own key, or [film]'s.
Scenario named_scenario(const Where& w, Context& cx, const std::string& name, const std::string& key) {
    const bool file = name.size() > 5 && name.ends_with(".toml");
    const std::string path = file ? (std::filesystem::path(cx.base_dir) / name).string()
                                  : (std::filesystem::path(cx.asset_dir) / (name + ".toml")).string();
    if (const auto known = cx.loaded.find(path); known != cx.loaded.end()) return known->second;
    if (!file && !std::filesystem::exists(path))
        w.fail(key, fmt::format("'{}' is neither a preset in {} nor a .toml file", shown_text(name), cx.asset_dir));
    try {
        LoadedScenario read = read_scenario_file(path, {}, cx.outputs);
        cx.warnings.insert(cx.warnings.end(), read.warnings.begin(), read.warnings.end());
        return cx.loaded[path] = read.scenario;
    } catch (const InputError& e) {
        w.fail(key, e.what());
    }
}

Scenario scenario_of(const Where& w, Context& cx, const toml::table& t, const std::string& prefix) {
    Scenario s;
    if (const toml::node* n = t.get("scenario")) {
        s = named_scenario(w, cx, film::text(w, *n, prefix + "scenario"), prefix + "scenario");
    } else if (!cx.default_scenario.empty()) {
        s = named_scenario(Where{cx.file, 0, "film"}, cx, cx.default_scenario, "scenario");
    }
    if (const toml::node* n = t.get("path")) {
        const std::string kind = film::text(w, *n, prefix + "path");
        if (kind == "spiral") s.path.kind = PathKind::spiral;
        else if (kind == "turnaround") s.path.kind = PathKind::turnaround;
        else w.fail(prefix + "path", fmt::format("'{}' is not a path: use \"spiral\" or \"turnaround\"", shown_text(kind)));
    }
    ScenarioValues set = 0;
    for (const KeyInfo& k : all_keys()) {
        if (!sets_scenario_value(k)) continue;
        const toml::node* n = t.get(k.name);
        if (!n) continue;
        const std::string key = prefix + std::string(k.name);
        if (k.scenario == value::bench_count) {
            const std::optional<std::int64_t> c = n->value_exact<std::int64_t>();
            if (!c || *c < 1 || *c > kMaxBenchCount)
                w.fail(key, fmt::format("must be a whole number of benches, 1 to {}", kMaxBenchCount));
            s.bench.bench_count = static_cast<int>(*c);
        } else {
            set_parameter(s, *find_sweep_parameter(hyphenated(k.key)), film::number(w, *n, key));
        }
        set |= k.scenario;
    }
    try {
        validate(s);
    } catch (const ScenarioError& e) {
        // Named by the shot's own key when it set one of the values the rule involves.
        std::string key = prefix + "scenario";
        for (const KeyInfo& k : all_keys())
            if (sets_scenario_value(k) && (e.values & k.scenario) && (set & k.scenario)) key = prefix + std::string(k.name);
        w.fail(key, e.what());
    }
    return s;
}

// One scene of a shot: the shot's own keys, with a pane's over them in a split.
ShotView view_of(const Where& w, Context& cx, const toml::table& shot, const toml::table* pane,
                 const std::string& prefix) {
    toml::table t = shot;
    if (pane)
        for (const auto& [k, v] : *pane) t.insert_or_assign(k, v);
    ShotView v;
    v.scenario = scenario_of(w, cx, t, prefix);
    const bool turn = v.scenario.path.kind == PathKind::turnaround;
    // The contest's runs as head travel: coiling in from the start to the first contact, the
    // turnaround 100 m either side of the turn (100 s at 1 m/s).
    v.from = {TimeRef::Anchor::travel, turn ? -100.0 : 0.0};
    v.to = turn ? TimeRef{TimeRef::Anchor::travel, 100.0} : TimeRef{TimeRef::Anchor::collision, 0.0};
    // A pane's keys are named with their place: split[2].to.
    auto key = [&](const char* k) { return (pane && pane->contains(k) ? prefix : std::string()) + k; };
    if (const toml::node* n = t.get("from")) v.from = film::time_ref(w, *n, key("from"));
    if (const toml::node* n = t.get("to")) v.to = film::time_ref(w, *n, key("to"));
    if (const toml::node* n = t.get("camera")) v.camera = film::camera(w, *n, key("camera"));
    if (const toml::node* n = t.get("speed_colours")) v.speed_colours = film::boolean(w, *n, key("speed_colours"));
    if (const toml::node* n = t.get("guides")) v.guides = film::boolean(w, *n, key("guides"));
    if (const toml::node* n = t.get("label")) v.label = film::text(w, *n, key("label"));
    return v;
}

void read_common(const Where& w, const toml::table& t, Shot& s) {
    if (const toml::node* n = t.get("rate")) s.rate = film::positive(w, *n, "rate", 1e6);
    if (const toml::node* n = t.get("duration")) s.duration = film::positive(w, *n, "duration", 3600);
    if (s.kind != Shot::Kind::title && s.rate.has_value() == s.duration.has_value())
        w.fail(s.rate ? "duration" : "rate", "give a rate (simulated seconds per second of film) or a duration, "
                                              "one of the two");
    if (s.kind == Shot::Kind::title && !s.duration) w.fail("duration", "a title card needs a duration, s");
    if (const toml::node* n = t.get("transition")) {
        if (n->is_string() && *n->value<std::string>() == "cut") {
        } else if (const toml::table* tt = n->as_table(); tt && tt->contains("crossfade")) {
            film::check_keys(w, *tt, {"crossfade"}, "a transition", "transition.");
            s.crossfade = film::positive(w, *tt->get("crossfade"), "transition.crossfade", 60);
        } else {
            w.fail("transition", "must be \"cut\" or {crossfade = SECONDS}");
        }
    }
    if (const toml::node* n = t.get("legend")) s.legend = film::boolean(w, *n, "legend");
    if (const toml::node* n = t.get("clock")) s.clock = film::boolean(w, *n, "clock");
    if (const toml::node* n = t.get("inset")) s.inset = film::boolean(w, *n, "inset");
    if (const toml::node* n = t.get("events")) s.events = film::boolean(w, *n, "events");
    if (const toml::node* n = t.get("text")) s.text = film::boolean(w, *n, "text");
    if (const toml::node* n = t.get("captions")) {
        const toml::array* a = n->as_array();
        if (!a) w.fail("captions", "must be a list of {text = \"...\", at = MOMENT, seconds = S}");
        if (a->size() > kMaxShotCaptions)
            w.fail("captions", fmt::format("has {} captions: a shot has at most {}", a->size(), kMaxShotCaptions));
        for (std::size_t i = 0; i < a->size(); ++i) {
            const std::string key = fmt::format("captions[{}]", i + 1);
            const toml::table* c = a->get(i)->as_table();
            if (!c || !c->contains("text")) w.fail(key, "must be a table with text = \"...\"");
            film::check_keys(w, *c, {"text", "at", "seconds"}, "a caption", key + ".");
            CaptionSpec spec{film::text(w, *c->get("text"), key + ".text"), std::nullopt, 3.0};
            if (const toml::node* at = c->get("at")) spec.at = film::time_ref(w, *at, key + ".at");
            if (const toml::node* sec = c->get("seconds")) spec.seconds = film::positive(w, *sec, key + ".seconds", 3600);
            s.captions.push_back(spec);
        }
    }
}

Shot shot_of(const Where& w, Context& cx, const toml::table& t) {
    Shot s;
    s.name = w.name;
    std::set<std::string> common = {"name", "rate", "duration", "transition", "legend", "clock", "inset",
                                    "events", "captions", "slow", "freeze", "text"};
    if (t.contains("title")) {
        s.kind = Shot::Kind::title;
        film::check_keys(w, t, {"name", "title", "subtitle", "duration", "transition"}, "a title card");
        s.title = film::text(w, *t.get("title"), "title");
        if (const toml::node* n = t.get("subtitle")) s.subtitle = film::text(w, *n, "subtitle");
        read_common(w, t, s);
        return s;
    }
    std::set<std::string> allowed = common;
    const std::set<std::string> scene = view_keys();
    allowed.insert(scene.begin(), scene.end());
    if (const toml::node* split = t.get("split")) {
        s.kind = Shot::Kind::split;
        allowed.insert("split");
        film::check_keys(w, t, allowed, "a split shot");
        const toml::array* a = split->as_array();
        if (!a || a->size() != 2) w.fail("split", "must list two scenes: split = [{...}, {...}]");
        toml::table shared = t;
        shared.erase("split");
        for (std::size_t i = 0; i < 2; ++i) {
            const std::string prefix = fmt::format("split[{}].", i + 1);
            const toml::table* pane = a->get(i)->as_table();
            if (!pane) w.fail(prefix.substr(0, prefix.size() - 1), "must be a table of a scene's keys");
            film::check_keys(w, *pane, scene, "a split scene", prefix);
            s.views.push_back(view_of(w, cx, shared, pane, prefix));
        }
    } else {
        film::check_keys(w, t, allowed, "a shot");
        s.views.push_back(view_of(w, cx, t, nullptr, ""));
    }
    read_common(w, t, s);
    if (const toml::node* n = t.get("slow")) {
        const toml::table* st = n->as_table();
        if (!st || !st->contains("at") || !st->contains("within") || !st->contains("rate"))
            w.fail("slow", "must be {at = MOMENT, within = SECONDS, rate = SIMULATED SECONDS PER SECOND}");
        if (s.kind == Shot::Kind::split) w.fail("slow", "is not allowed in a split shot: its scenes keep one clock");
        film::check_keys(w, *st, {"at", "within", "rate"}, "slow motion", "slow.");
        s.slow = SlowMotion{film::time_ref(w, *st->get("at"), "slow.at"),
                            film::positive(w, *st->get("within"), "slow.within", 1e6),
                            film::positive(w, *st->get("rate"), "slow.rate", 1e6)};
    }
    if (const toml::node* n = t.get("freeze")) {
        const toml::table* ft = n->as_table();
        if (!ft || !ft->contains("seconds")) w.fail("freeze", "must be {seconds = S} or {seconds = S, zoom = METRES}");
        film::check_keys(w, *ft, {"seconds", "zoom"}, "a freeze", "freeze.");
        s.freeze.seconds = film::positive(w, *ft->get("seconds"), "freeze.seconds", 3600);
        if (const toml::node* z = ft->get("zoom")) {
            if (s.kind == Shot::Kind::split) w.fail("freeze.zoom", "is not allowed in a split shot");
            const double m = film::number(w, *z, "freeze.zoom");
            if (!(m >= kMinViewExtent && m <= kMaxViewExtent))
                w.fail("freeze.zoom", fmt::format("= {} is not allowed: a window is {:g}..{:g} m across", m,
                                                  kMinViewExtent, kMaxViewExtent));
            s.freeze.zoom = m;
        }
    }
    return s;
}

}  // namespace

Storyboard parse_storyboard(const std::string& toml_text, const std::string& file, const std::string& base_dir,
                            const std::string& asset_dir, RunOutputs* outputs) {
    Storyboard board;
    board.file = file;
    toml::table root;
    try {
        root = toml::parse(toml_text, file);
    } catch (const toml::parse_error& e) {
        throw InputError(fmt::format("storyboard '{}' is not valid TOML (line {}, column {}): {}", file,
                                     e.source().begin.line, e.source().begin.column, e.description()));
    }
    Context cx{file, base_dir, asset_dir.empty() ? find_asset_dir() : asset_dir, "", {}, outputs, {}};
    board.asset_dir = cx.asset_dir;
    const Where top{file, 0, "film"};
    film::check_keys(top, root, {"film", "shot"}, "a storyboard (a [film] table and [[shot]] tables)");
    if (const toml::node* f = root.get("film")) {
        const toml::table* t = f->as_table();
        if (!t) top.fail("film", "must be a table: [film]");
        film::check_keys(top, *t, {"size", "fps", "theme", "scenario", "lang"}, "[film]");
        if (const toml::node* n = t->get("size")) std::tie(board.film.width, board.film.height) = film::size(top, *n, "size");
        if (const toml::node* n = t->get("fps")) {
            // The video's range, checked here so that the error names this key.
            board.film.fps = film::number(top, *n, "fps");
            if (!(board.film.fps >= kMinVideoFps && board.film.fps <= kMaxVideoFps))
                top.fail("fps", fmt::format("= {} is not allowed: use a rate from {} to {} frames per second",
                                            board.film.fps, kMinVideoFps, kMaxVideoFps));
        }
        if (const toml::node* n = t->get("theme")) board.film.theme = film::text(top, *n, "theme");
        if (const toml::node* n = t->get("lang")) {
            const std::string code = film::text(top, *n, "lang");
            try {
                board.film.language = parse_language(code);
            } catch (const InputError& e) {
                top.fail("lang", fmt::format("\"{}\" is not allowed: {}", code, e.allowed()));
            }
        }
        if (const toml::node* n = t->get("scenario")) cx.default_scenario = film::text(top, *n, "scenario");
    }
    const toml::array* shots = root.get_as<toml::array>("shot");
    if (!shots || shots->empty() || !shots->is_array_of_tables())
        top.fail("shot", "a storyboard needs at least one [[shot]] table");
    if (shots->size() > kMaxStoryboardShots)
        top.fail("shot", fmt::format("the storyboard has {} shots: a film has at most {}", shots->size(),
                                     kMaxStoryboardShots));
    for (std::size_t i = 0; i < shots->size(); ++i) {
        const toml::table& t = *shots->get(i)->as_table();
        Where w{file, static_cast<int>(i + 1), fmt::format("shot {}", i + 1)};
        if (const toml::node* n = t.get("name")) w.name = fmt::format("\"{}\"", film::text(w, *n, "name"));
        board.shots.push_back(shot_of(w, cx, t));
    }
    board.warnings = std::move(cx.warnings);
    return board;
}

Storyboard load_storyboard(const std::string& path, const std::string& asset_dir, RunOutputs* outputs) {
    const std::string text = read_toml_input(path, "storyboard", outputs);
    const std::string base = std::filesystem::path(path).parent_path().string();
    return parse_storyboard(text, path, base.empty() ? "." : base, asset_dir, outputs);
}

}  // namespace dragon
