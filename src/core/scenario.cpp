#include "dragon/scenario.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dragon/path.hpp"

namespace dragon {

namespace {

void require_positive(const char* name, double v) {
    if (!std::isfinite(v) || v <= 0.0)
        throw InputError(fmt::format("{} = {} is not allowed: it must be a finite number > 0", name, v));
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

void require_in(const char* name, double v, Range r) {
    if (!(v >= r.lo && v <= r.hi))  // NaN fails too
        throw InputError(fmt::format("{} = {} is not allowed: it must be from {}{} to {}{}", name, v, r.lo,
                                     r.unit, r.hi, r.unit));
}

}  // namespace

const char* to_string(PathKind k) { return k == PathKind::spiral ? "spiral" : "turnaround"; }

void validate(const Scenario& s) {
    const BenchSpec& b = s.bench;
    if (b.bench_count < 1 || b.bench_count > 1000000)
        throw InputError(fmt::format("body count {} is not allowed: the chain needs 1 to 1000000 benches",
                                     b.bench_count));
    require_positive("head length", b.head_length);
    require_positive("body length", b.body_length);
    require_positive("width", b.width);
    if (!std::isfinite(b.hole_offset) || b.hole_offset < 0.0)
        throw InputError(fmt::format("hole offset {} is not allowed: it must be >= 0", b.hole_offset));
    require_in("head length", b.head_length, kLength);
    require_in("body length", b.body_length, kLength);
    require_in("width", b.width, kLength);
    const double shortest = b.bench_count > 1 ? std::min(b.head_length, b.body_length) : b.head_length;
    // The holes at least 1 mm apart on every board: a link of zero length has no direction.
    if (!(shortest - 2.0 * b.hole_offset >= kLength.lo))
        throw InputError(fmt::format("hole offset {} is not allowed: it must be less than half the "
                                     "shortest board ({} m) by at least 0.5 mm", b.hole_offset, 0.5 * shortest));
    require_positive("pitch", s.path.pitch);
    require_positive("head speed", s.head_speed);
    require_positive("start turn", s.path.start_turn);
    require_positive("turn radius", s.path.turn_radius);
    require_positive("turn pitch", s.path.turn_pitch);
    require_positive("arc ratio", s.path.arc_ratio);
    require_in("pitch", s.path.pitch, kLength);
    require_in("head speed", s.head_speed, kSpeed);
    require_in("start turn", s.path.start_turn, kTurns);
    require_in("turn radius", s.path.turn_radius, kLength);
    require_in("turn pitch", s.path.turn_pitch, kLength);
    require_in("arc ratio", s.path.arc_ratio, kRatio);
    // The chain at the start, as far out as it goes: the head's arc length from the centre (the
    // head starts on the plain spiral's turn start_turn, or on the turnaround's coil-in spiral
    // at the turning space), plus the chain behind it.
    const bool spiral = s.path.kind == PathKind::spiral;
    const Spiral coil(s.coil_pitch());
    constexpr double kTwoPi = 6.283185307179586476925286766559;
    const double head = coil.length_to(spiral ? kTwoPi * s.path.start_turn : s.path.turn_radius / coil.b());
    if (!(head + b.chain_length() <= kMaxReach))
        throw InputError(fmt::format("{} benches {}: the chain would reach {:.4g} m along the spiral from "
                                     "its centre (the head {:.4g} m, the chain {:.4g} m); at most {:.0f} m "
                                     "keeps positions to 1e-8 m", b.bench_count,
                                     spiral ? "from this start turn and pitch" : "at this turn radius and pitch",
                                     head + b.chain_length(), head, b.chain_length(), kMaxReach));
    // Benches on neighbouring turns sit one pitch apart, centre line to centre line: a board at
    // least as wide as the pitch overlaps the next turn from the first instant.
    const double pitch = s.coil_pitch();
    if (pitch <= b.width)
        throw InputError(fmt::format("pitch {} is not allowed with width {}: the pitch must exceed "
                                     "the bench width, or the chain does not fit between the turns",
                                     pitch, b.width));
}

Scenario load_scenario(const std::string& path, Scenario base) {
    std::ifstream in(path);
    if (!in) throw InputError(fmt::format("scenario file '{}' cannot be read", path));
    std::stringstream text;
    text << in.rdbuf();
    toml::table root;
    try {
        root = toml::parse(text.str(), path);
    } catch (const toml::parse_error& e) {
        const auto& where = e.source().begin;
        throw InputError(fmt::format("scenario file '{}' is not valid TOML (line {}, column {}): {}",
                                     path, where.line, where.column, e.description()));
    }

    Scenario s = base;
    const std::set<std::string> sections = {"dragon", "path", "motion"};
    for (const auto& [key, node] : root) {
        if (!sections.count(std::string(key.str())) || !node.is_table())
            throw InputError(fmt::format("scenario file '{}': unknown section '{}' (allowed: [dragon], "
                                         "[path], [motion])", path, key.str()));
    }
    auto number = [&](const toml::table& t, const std::string& section, const std::string& key,
                      double& dst) {
        const toml::node* n = t.get(key);
        if (!n) return;
        if (auto v = n->value<double>()) { dst = *v; return; }
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
                                             path, section, key.str(), list));
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
        }
        number(*t, "dragon", "head_length", s.bench.head_length);
        number(*t, "dragon", "body_length", s.bench.body_length);
        number(*t, "dragon", "width", s.bench.width);
        number(*t, "dragon", "hole_offset", s.bench.hole_offset);
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
        number(*t, "path", "pitch", s.path.pitch);
        number(*t, "path", "start_turn", s.path.start_turn);
        number(*t, "path", "turn_radius", s.path.turn_radius);
        number(*t, "path", "turn_pitch", s.path.turn_pitch);
        number(*t, "path", "arc_ratio", s.path.arc_ratio);
    }
    if (const toml::table* t = root["motion"].as_table()) {
        check_keys(*t, "motion", {"head_speed"});
        number(*t, "motion", "head_speed", s.head_speed);
    }
    return s;
}

}  // namespace dragon
