// A sweep described in a TOML file, parsed from its text (sweep_file_read.cpp reads the file):
// the command line's keys, a scenario value named as TOML names it (body_length), so that a map
// can be made again from its file (assets/sweeps/). The flag's spelling (body-length), the old
// one, is read with a warning.
#include <fmt/format.h>
#include <toml++/toml.h>

#include "dragon/shown_text.hpp"
#include "dragon/scenario.hpp"
#include "dragon/sweep.hpp"

namespace dragon {

namespace {

// A number or a string as the text a command line would hold.
std::optional<std::string> as_text(const toml::node& n) {
    if (auto i = n.value_exact<int64_t>()) return fmt::format("{}", *i);
    if (auto d = n.value_exact<double>()) return fmt::format("{}", *d);
    if (auto s = n.value_exact<std::string>()) return *s;
    return std::nullopt;
}

// A string, or an array of strings, as a list.
std::vector<std::string> text_list(const toml::node& n, const std::string& path, const char* key) {
    if (auto s = n.value_exact<std::string>()) return {*s};
    std::vector<std::string> out;
    if (const toml::array* a = n.as_array()) {
        for (const toml::node& item : *a) {
            auto s = item.value_exact<std::string>();
            if (!s) break;
            out.push_back(*s);
        }
        if (out.size() == a->size()) return out;
    }
    throw InputError(fmt::format("sweep file '{}': {} must be a string or a list of strings", path, key));
}

// `name` as seen from the file `origin`: as it is when absolute or when the origin has no folder,
// else in the origin's folder. Text only (the core has no file system): std::filesystem's
// parent_path and operator/ give the same for these.
std::string beside(const std::string& origin, const std::string& name) {
    if (!name.empty() && name.front() == '/') return name;
    const std::size_t slash = origin.rfind('/');
    if (slash == std::string::npos) return name;
    return origin.substr(0, slash + 1) + name;
}

}  // namespace

SweepFile parse_sweep_file(const std::string& text, const std::string& origin) {
    const std::string where = fmt::format("sweep file '{}'", shown_text(origin, 4096));
    toml::table root;
    try {
        root = toml::parse(text, origin);
    } catch (const toml::parse_error& e) {
        const auto& at = e.source().begin;
        throw InputError(fmt::format("{} is not valid TOML (line {}, column {}): {}", where, at.line, at.column,
                                     e.description()));
    }
    SweepFile out;
    // The scenario value a name sets: today's name (underscores), or the flag's (hyphens), the
    // old one, which `warn` then says in one line; nullptr for no scenario value.
    const auto scenario_value_named = [](const std::string& name) -> const KeyInfo* {
        const KeyInfo* k = find_key(name);
        return k && in_scenario_file(k->key) && k->key != Key::path ? k : nullptr;
    };
    const auto warn = [&](const KeyInfo& k, const std::string& old_name, const std::string& written,
                          const std::string& today) {
        out.warnings.push_back({k.key, old_name, fmt::format("{}: {} is an old name: write {}", where, written, today)});
    };
    const auto value_names = [] {
        std::string list;
        for (const KeyInfo& k : all_keys())
            if (in_scenario_file(k.key) && k.key != Key::path) list += (list.empty() ? "" : ", ") + std::string(k.name);
        return list;
    };
    for (const auto& [key, node] : root) {
        const std::string name(key.str());
        if (name == "measure") {
            out.measures = text_list(node, origin, "measure");
        } else if (name == "vary") {
            // Each NAME=VALUES with today's name; kept with the flag's name, as --vary takes it.
            for (const std::string& spec : text_list(node, origin, "vary")) {
                const std::size_t eq = spec.find('=');
                const std::string axis = spec.substr(0, eq);
                const KeyInfo* k = eq == std::string::npos ? nullptr : scenario_value_named(axis);
                if (!k)
                    throw InputError(fmt::format("{}: vary \"{}\" is not allowed: give NAME=FROM:TO:COUNT or "
                                                 "NAME=V1,V2,... with NAME one of {}", where, shown_text(spec), value_names()));
                const std::string values = spec.substr(eq);
                if (k->name != axis)
                    warn(*k, axis, fmt::format("vary \"{}\"", shown_text(spec)),
                         fmt::format("\"{}{}\"", k->name, shown_text(values)));
                out.vary.push_back(hyphenated(k->key) + values);
            }
        } else if (name == "scenario") {
            auto s = node.value_exact<std::string>();
            if (!s) throw InputError(fmt::format("{}: scenario must be a file name", where));
            // Relative to the sweep file, so that the pair can move together.
            out.scenario = beside(origin, *s);
        } else if (const toml::table* t = node.as_table()) {
            for (const auto& [k, v] : *t) {
                const std::string key_name(k.str());
                const std::optional<std::string> value = as_text(v);
                if (!value)
                    throw InputError(fmt::format("{}: [{}] {} must be a number or a string", where, shown_text(name),
                                                 shown_text(key_name)));
                if (name != "fixed") {
                    out.options.push_back({name, key_name, *value});
                    continue;
                }
                const KeyInfo* info = scenario_value_named(key_name);
                if (!info)
                    throw InputError(fmt::format("{}: [fixed] {} is not a scenario value (allowed: {})", where,
                                                 shown_text(key_name), value_names()));
                if (info->name != key_name)
                    warn(*info, key_name, fmt::format("[fixed] {}", shown_text(key_name)),
                         fmt::format("{} = {}", info->name, shown_text(*value)));
                out.fixed.emplace_back(std::string(info->name), *value);
            }
        } else {
            throw InputError(fmt::format("{}: unknown key '{}' (allowed: measure, vary, scenario, "
                                         "[fixed] and a table of options per measure)", where, shown_text(name)));
        }
    }
    return out;
}

}  // namespace dragon
