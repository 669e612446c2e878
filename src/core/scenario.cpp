#include "dragon/scenario.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

namespace dragon {

namespace {

void require_positive(const char* name, double v) {
    if (!std::isfinite(v) || v <= 0.0)
        throw InputError(fmt::format("{} = {} is not allowed: it must be a finite number > 0", name, v));
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
    const double shortest = b.bench_count > 1 ? std::min(b.head_length, b.body_length) : b.head_length;
    if (b.hole_offset >= 0.5 * shortest)
        throw InputError(fmt::format("hole offset {} is not allowed: it must be less than half the "
                                     "shortest board ({} m)", b.hole_offset, 0.5 * shortest));
    require_positive("pitch", s.path.pitch);
    require_positive("head speed", s.head_speed);
    require_positive("start turn", s.path.start_turn);
    require_positive("turn radius", s.path.turn_radius);
    require_positive("turn pitch", s.path.turn_pitch);
    require_positive("arc ratio", s.path.arc_ratio);
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
