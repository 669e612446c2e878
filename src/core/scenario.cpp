#include "dragon/constants.hpp"
#include "dragon/scenario.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dragon/shown_text.hpp"
#include "dragon/path.hpp"

namespace dragon {

namespace {

// A rule between values, or on one, failed: the value the sentence is about, what is allowed,
// the sentence, and which values the rule involves.
[[noreturn]] void refuse(ScenarioValues involved, Key key, std::string value, std::string allowed,
                         const std::string& what) {
    throw ScenarioError(key, std::move(value), std::move(allowed), what, involved);
}

// The usual sentence: "{words} = {value} is not allowed: {allowed}".
[[noreturn]] void refuse_value(ScenarioValues v, double x, const std::string& allowed) {
    const Key key = scenario_key(v);
    const std::string shown = error_value(x);
    refuse(v, key, shown, allowed, fmt::format("{} = {} is not allowed: {}", key_info(key).words, shown, allowed));
}

void require_positive(ScenarioValues v, double x) {
    if (!std::isfinite(x) || x <= 0.0) refuse_value(v, x, "it must be a finite number > 0");
}

// Each value's range: wide enough for any dragon (a 1 mm toy to a 1 km parade, a snail's pace
// to a rocket's), narrow enough that the geometry stays well inside double precision: a path
// parameter of theta ~ 1e5 rad still leaves positions good to ~1e-11 relative, and no length
// ratio exceeds ~1e6. Beyond them the fuzzer (tests/fuzz/fuzz_chain) found infinite and NaN
// positions (a pitch of 3e26 m, say) that validate() let through.
struct Range {
    double lo, hi;
    const char* unit;
};
constexpr Range kLength{1e-3, 1e3, " m"};      // boards, width, pitches, turning radius
constexpr Range kTurns{1e-3, 1e4, ""};          // start turn: theta up to 2 pi 1e4 ~ 6e4 rad
constexpr Range kRatio{1e-3, 1e3, ""};          // arc ratio r1 / r2
constexpr Range kSpeed{1e-9, 1e9, " m/s"};      // head speed: only the time scale depends on it

void require_in(ScenarioValues v, double x, Range r) {
    require_positive(v, x);
    if (!(x >= r.lo && x <= r.hi)) refuse_value(v, x, fmt::format("it must be from {}{} to {}{}", r.lo, r.unit, r.hi, r.unit));
}

bool has(ScenarioValues set, ScenarioValues wanted) { return (set & wanted) == wanted; }

// The chain at the start, as far out as it goes: the head's arc length from the centre (on the
// plain spiral's turn start_turn, or on the turnaround's coil-in spiral at the turning space),
// plus the chain behind it.
void require_reach(const Scenario& s, bool spiral) {
    const BenchSpec& b = s.bench;
    const Spiral coil(spiral ? s.path.pitch : s.path.turn_pitch);
    const double head = coil.length_to(spiral ? kTwoPi * s.path.start_turn : s.path.turn_radius / coil.b());
    if (!(head + b.chain_length() <= kMaxReach))
        refuse(value::bench | (spiral ? value::pitch | value::start_turn : value::turn_pitch | value::turn_radius),
               Key::bench_count, std::to_string(b.bench_count),
               fmt::format("at most {:.0f} m of chain and path from the spiral's centre", kMaxReach),
               fmt::format("{} {} {}: the chain would reach {:.4g} m along the spiral from its centre (the "
                           "head {:.4g} m, the chain {:.4g} m); at most {:.0f} m keeps positions to 1e-8 m",
                           b.bench_count, b.bench_count == 1 ? "bench" : "benches", spiral ? "from this start turn and pitch" : "at this turn radius and pitch",
                           head + b.chain_length(), head, b.chain_length(), kMaxReach));
}

// Benches on neighbouring turns sit one pitch apart, centre line to centre line: a board at
// least as wide as the pitch overlaps the next turn from the first instant.
void require_wider_pitch(ScenarioValues pitch_value, double pitch, double width) {
    if (pitch <= width)
        refuse(pitch_value | value::width, scenario_key(pitch_value), error_value(pitch),
               fmt::format("the pitch must exceed the bench width, {} m", width),
               fmt::format("pitch {} is not allowed with width {}: the pitch must exceed the bench width, or the "
                           "chain does not fit between the turns", pitch, width));
}

}  // namespace

void refuse_bench_count(const std::string& given) {
    const std::string allowed = fmt::format("the chain needs 1 to {} benches", kMaxBenchCount);
    throw ScenarioError(Key::bench_count, given, allowed, fmt::format("bench count {} is not allowed: {}", given, allowed),
                        value::bench_count);
}

const char* to_string(PathKind k) { return k == PathKind::spiral ? "spiral" : "turnaround"; }

ScenarioValues values_read(PathKind kind) {
    const ScenarioValues path = kind == PathKind::spiral ? value::pitch | value::start_turn
                                                         : value::turn_radius | value::turn_pitch | value::arc_ratio;
    return value::bench | value::head_speed | path;
}

void validate(const Scenario& s) { validate(s, values_read(s.path.kind)); }

void validate(const Scenario& s, ScenarioValues values) {
    using namespace value;
    const BenchSpec& b = s.bench;
    if ((values & bench_count) && (b.bench_count < 1 || b.bench_count > kMaxBenchCount))
        refuse_bench_count(std::to_string(b.bench_count));
    if (values & head_length) require_in(head_length, b.head_length, kLength);
    if (values & body_length) require_in(body_length, b.body_length, kLength);
    if (values & width) require_in(width, b.width, kLength);
    if ((values & hole_offset) && !(std::isfinite(b.hole_offset) && b.hole_offset >= 0.0))
        refuse_value(hole_offset, b.hole_offset, "it must be a finite number >= 0 m");
    if (has(values, bench_count | head_length | body_length | hole_offset)) {
        const double shortest = b.bench_count > 1 ? std::min(b.head_length, b.body_length) : b.head_length;
        // The holes at least 1 mm apart on every board: a link of zero length has no direction.
        if (!(shortest - 2.0 * b.hole_offset >= kLength.lo))
            refuse(bench_count | head_length | body_length | hole_offset, Key::hole_offset, error_value(b.hole_offset),
                   fmt::format("it must be less than half the shortest board ({} m) by at least 0.5 mm", 0.5 * shortest),
                   fmt::format("hole offset {} is not allowed: it must be less than half the shortest board "
                               "({} m) by at least 0.5 mm", b.hole_offset, 0.5 * shortest));
    }
    if (values & head_speed) require_in(head_speed, s.head_speed, kSpeed);
    if (values & pitch) require_in(pitch, s.path.pitch, kLength);
    if (values & start_turn) require_in(start_turn, s.path.start_turn, kTurns);
    if (values & turn_radius) require_in(turn_radius, s.path.turn_radius, kLength);
    if (values & turn_pitch) require_in(turn_pitch, s.path.turn_pitch, kLength);
    if (values & arc_ratio) require_in(arc_ratio, s.path.arc_ratio, kRatio);
    if (has(values, bench | pitch | start_turn)) require_reach(s, true);
    if (has(values, bench | turn_pitch | turn_radius)) require_reach(s, false);
    if (has(values, pitch | width)) require_wider_pitch(pitch, s.path.pitch, b.width);
    if (has(values, turn_pitch | width)) require_wider_pitch(turn_pitch, s.path.turn_pitch, b.width);
}

LoadedScenario parse_scenario_toml(const std::string& text, const std::string& origin, Scenario base) {
    const std::string& path = origin;  // as the messages below name the text
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        const auto& where = e.source().begin;
        throw InputError(fmt::format("scenario file '{}' is not valid TOML (line {}, column {}): {}",
                                     path, where.line, where.column, e.description()));
    }

    LoadedScenario out{base, 0};
    Scenario& s = out.scenario;
    const std::set<std::string> sections = {"dragon", "path", "motion"};
    for (const auto& [key, node] : root) {
        const std::string name(key.str());
        if (node.is_table() && sections.count(name)) continue;
        if (node.is_array_of_tables() && sections.count(name))
            throw InputError(fmt::format("scenario file '{}': [[{}]] is not allowed: write the section once, as [{}]",
                                         path, name, name));
        if (node.is_table())
            throw InputError(fmt::format("scenario file '{}': unknown section [{}] (allowed: [dragon], [path], "
                                         "[motion])", shown_text(path, 4096), shown_text(name)));
        throw InputError(fmt::format("scenario file '{}': key '{}' is outside any section: keys belong under "
                                     "[dragon], [path] or [motion]", shown_text(path, 4096), shown_text(name)));
    }
    auto number = [&](const toml::table& t, const std::string& section, const std::string& key, double& dst,
                      ScenarioValues v) {
        const toml::node* n = t.get(key);
        if (!n) return;
        // A whole number too is a number, however large: out of range is validate()'s to say
        // (value<double>() gives none for an integer a double cannot hold exactly).
        std::optional<double> x = n->value<double>();
        if (!x && n->is_integer()) x = static_cast<double>(*n->value_exact<std::int64_t>());
        if (x) {
            dst = *x;
            out.values |= v;
            return;
        }
        throw InputError(fmt::format("scenario file '{}': [{}] {} must be a number", path, section, key));
    };
    auto check_keys = [&](const toml::table& t, const std::string& section,
                          const std::set<std::string>& allowed) {
        for (const auto& [key, node] : t) {
            (void)node;
            if (!allowed.count(std::string(key.str()))) {
                std::string list;
                for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
                throw InputError(fmt::format("scenario file '{}': unknown key [{}] {} (allowed: {})",
                                             shown_text(path, 4096), section, shown_text(std::string(key.str())), list));
            }
        }
    };

    if (const toml::table* t = root["dragon"].as_table()) {
        check_keys(*t, "dragon", {"bench_count", "head_length", "body_length", "width", "hole_offset"});
        if (const toml::node* n = t->get("bench_count")) {
            auto v = n->value_exact<int64_t>();
            if (!v || *v < 1 || *v > 1000000)
                throw InputError(fmt::format("scenario file '{}': [dragon] bench_count must be an "
                                             "integer from 1 to 1000000", path));
            s.bench.bench_count = static_cast<int>(*v);
            out.values |= value::bench_count;
        }
        number(*t, "dragon", "head_length", s.bench.head_length, value::head_length);
        number(*t, "dragon", "body_length", s.bench.body_length, value::body_length);
        number(*t, "dragon", "width", s.bench.width, value::width);
        number(*t, "dragon", "hole_offset", s.bench.hole_offset, value::hole_offset);
    }
    if (const toml::table* t = root["path"].as_table()) {
        check_keys(*t, "path", {"kind", "pitch", "start_turn", "turn_radius", "turn_pitch", "arc_ratio"});
        if (const toml::node* n = t->get("kind")) {
            auto v = n->value<std::string>();
            if (v && *v == "spiral") s.path.kind = PathKind::spiral;
            else if (v && *v == "turnaround") s.path.kind = PathKind::turnaround;
            else throw InputError(fmt::format("scenario file '{}': [path] kind must be \"spiral\" or "
                                              "\"turnaround\"", path));
        }
        number(*t, "path", "pitch", s.path.pitch, value::pitch);
        number(*t, "path", "start_turn", s.path.start_turn, value::start_turn);
        number(*t, "path", "turn_radius", s.path.turn_radius, value::turn_radius);
        number(*t, "path", "turn_pitch", s.path.turn_pitch, value::turn_pitch);
        number(*t, "path", "arc_ratio", s.path.arc_ratio, value::arc_ratio);
    }
    if (const toml::table* t = root["motion"].as_table()) {
        check_keys(*t, "motion", {"head_speed"});
        number(*t, "motion", "head_speed", s.head_speed, value::head_speed);
    }
    return out;
}

}  // namespace dragon
