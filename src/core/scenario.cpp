#include "dragon/constants.hpp"
#include "dragon/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dragon/shown_text.hpp"
#include "dragon/path.hpp"
#include "scenario_number.hpp"

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

namespace {

constexpr OldScenarioName kOldNames[] = {
    {"dragon", "bench_count", Key::bench_count}, {"dragon", "head_length", Key::head_length},
    {"dragon", "body_length", Key::body_length}, {"dragon", "width", Key::width},
    {"dragon", "hole_offset", Key::hole_offset}, {"path", "kind", Key::path},
    {"path", "pitch", Key::pitch},               {"path", "start_turn", Key::start_turn},
    {"path", "turn_radius", Key::turn_radius},   {"path", "turn_pitch", Key::turn_pitch},
    {"path", "arc_ratio", Key::arc_ratio},       {"motion", "head_speed", Key::speed},
};

bool is_old_section(std::string_view name) { return name == "dragon" || name == "path" || name == "motion"; }

// A value as the file gives it, for messages: a string in double quotes, a number as short as
// it reads back (2.2, not toml++'s 2.2000000000000002).
std::string toml_text(const toml::node& n) {
    if (const std::optional<std::string> text = n.value_exact<std::string>()) return "\"" + shown_text(*text) + "\"";
    if (const std::optional<std::int64_t> i = n.value_exact<std::int64_t>()) return std::to_string(*i);
    if (const std::optional<double> d = n.value_exact<double>()) return error_value(*d);
    std::ostringstream out;
    n.visit([&](const auto& v) { out << v; });
    return shown_text(out.str());
}

// Whether the text has today's `path = ...` at its top level and the old section [path]: TOML
// refuses a key and a table of one name, so such a file never parses, and the parser's words
// would not say why.
bool has_path_key_and_section(const std::string& text) {
    const auto skip_blanks = [](std::string_view v) {
        while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
        return v;
    };
    // "path" then, past blanks, `next`: "path =", "[ path ]".
    const auto path_then = [&](std::string_view v, char next) {
        if (!v.starts_with("path")) return false;
        v = skip_blanks(v.substr(4));
        return !v.empty() && v.front() == next;
    };
    bool top = true, key = false, section = false;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        const std::string_view line = skip_blanks(std::string_view(text).substr(at, end - at));
        at = end + 1;
        if (line.starts_with('[')) {
            top = false;
            section = section || path_then(skip_blanks(line.substr(1)), ']');
        } else if (top) {
            key = key || path_then(line, '=');
        }
    }
    return key && section;
}

// The allowed keys, for a message: the key table's names.
std::string allowed_keys() {
    std::string out;
    for (const KeyInfo& k : all_keys())
        if (in_scenario_file(k.key)) out += (out.empty() ? "" : ", ") + std::string(k.name);
    return out;
}

// Reads one file's keys into a LoadedScenario, each key once, whichever form names it.
class ScenarioReader {
public:
    ScenarioReader(const std::string& origin, Scenario base)
        : where_(fmt::format("scenario file '{}'", shown_text(origin, 4096))), out_{base, 0, {}} {}

    // `written`: the key as the file names it ("pitch", "[path] pitch"), for messages.
    void take(Key key, const toml::node& n, const std::string& written) {
        const std::string shown = toml_text(n);
        for (const auto& [k, first] : taken_)
            if (k == key)
                throw InputError(key, shown, fmt::format("{} once", key_info(key).name),
                                 fmt::format("{}: {} and {} both set the {}: write it once, as {} at the top level",
                                             where_, first, written, key_info(key).words, key_info(key).name));
        taken_.emplace_back(key, written);
        Scenario& s = out_.scenario;
        if (key == Key::path) {
            const std::optional<std::string> v = n.value_exact<std::string>();
            if (v && *v == "spiral") s.path.kind = PathKind::spiral;
            else if (v && *v == "turnaround") s.path.kind = PathKind::turnaround;
            else refuse(key, shown, "\"spiral\" or \"turnaround\"", written);
            return;
        }
        if (key == Key::bench_count) {
            const std::optional<std::int64_t> v = n.value_exact<std::int64_t>();
            if (!v || *v < 1 || *v > kMaxBenchCount)
                refuse(key, shown, fmt::format("a whole number of benches, 1 to {}", kMaxBenchCount), written);
            s.bench.bench_count = static_cast<int>(*v);
            out_.values |= value::bench_count;
            return;
        }
        // A whole number too is a number, however large: out of range is validate()'s to say
        // (value<double>() gives none for an integer a double cannot hold exactly).
        std::optional<double> x = n.value<double>();
        if (!x && n.is_integer()) x = static_cast<double>(*n.value_exact<std::int64_t>());
        if (!x) refuse(key, shown, "a number", written);
        const ScenarioValues v = key_info(key).scenario;
        *scenario_number(s, v) = *x;
        out_.values |= v;
    }

    // An old name read: one warning, naming the key today and the value to write.
    void warn_old(Key key, const std::string& written, const toml::node& n) {
        out_.warnings.push_back({key, written,
                                 fmt::format("{}: {} is an old name: write {} = {} at the top level", where_, written,
                                             key_info(key).name, toml_text(n))});
    }

    const std::string& where() const { return where_; }
    LoadedScenario result() && { return std::move(out_); }

private:
    [[noreturn]] void refuse(Key key, const std::string& shown, const std::string& allowed,
                             const std::string& written) const {
        throw InputError(key, shown, allowed,
                         fmt::format("{}: {} = {} is not allowed: give {}", where_, written, shown, allowed));
    }


    std::string where_;
    LoadedScenario out_;
    std::vector<std::pair<Key, std::string>> taken_;  // each key read, as the file named it
};

}  // namespace

std::span<const OldScenarioName> old_scenario_names() { return kOldNames; }

bool in_scenario_file(Key k) { return k == Key::path || key_info(k).scenario != 0; }

LoadedScenario parse_scenario_toml(const std::string& text, const std::string& origin, Scenario base) {
    toml::table root;
    try {
        root = toml::parse(text, origin);
    } catch (const toml::parse_error& e) {
        if (has_path_key_and_section(text))
            throw InputError(Key::path, "[path]", "path once",
                             fmt::format("scenario file '{}': path and the old section [path] cannot both be in one "
                                         "file (TOML takes one of the two): write [path]'s keys at the top level",
                                         shown_text(origin, 4096)));
        const auto& where = e.source().begin;
        throw InputError(fmt::format("scenario file '{}' is not valid TOML (line {}, column {}): {}",
                                     shown_text(origin, 4096), where.line, where.column, e.description()));
    }
    ScenarioReader reader(origin, base);
    const std::string& where = reader.where();
    // Today's keys first, then the old sections': a key in both forms is refused naming both.
    for (const auto& [key, node] : root) {
        const std::string name(key.str());
        if (is_old_section(name) && node.is_table()) continue;
        if (is_old_section(name) && node.is_array_of_tables())
            throw InputError(fmt::format("{}: [[{}]] is not allowed: write its keys at the top level ({})", where,
                                         name, allowed_keys()));
        if (node.is_table())
            throw InputError(fmt::format("{}: unknown section [{}]: write the keys at the top level (allowed: {})",
                                         where, shown_text(name), allowed_keys()));
        const KeyInfo* info = find_toml_key(name);
        if (!info || !in_scenario_file(info->key))
            throw InputError(fmt::format("{}: unknown key '{}' (allowed: {})", where, shown_text(name), allowed_keys()));
        reader.take(info->key, node, name);
    }
    for (const std::string_view section : {"dragon", "path", "motion"}) {
        const toml::table* t = root.get_as<toml::table>(section);
        if (!t) continue;
        for (const auto& [key, node] : *t) {
            const std::string name(key.str());
            const auto old = std::find_if(std::begin(kOldNames), std::end(kOldNames), [&](const OldScenarioName& o) {
                return o.section == section && o.name == name;
            });
            if (old == std::end(kOldNames))
                throw InputError(fmt::format("{}: unknown key [{}] {} (allowed: {}, at the top level)", where, section,
                                             shown_text(name), allowed_keys()));
            const std::string written = fmt::format("[{}] {}", section, name);
            reader.take(old->key, node, written);
            reader.warn_old(old->key, written, node);
        }
    }
    return std::move(reader).result();
}

}  // namespace dragon
