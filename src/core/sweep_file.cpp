// A sweep described in a TOML file: the same keys as the command line's, so that a map can be
// made again from its file (assets/sweeps/).
#include <fmt/format.h>
#include <toml++/toml.h>

#include "dragon/shown_text.hpp"
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
    const std::string& path = origin;  // as the messages below name the text
    toml::table root;
    try {
        root = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        const auto& where = e.source().begin;
        throw InputError(fmt::format("sweep file '{}' is not valid TOML (line {}, column {}): {}", path, where.line,
                                     where.column, e.description()));
    }
    SweepFile out;
    for (const auto& [key, node] : root) {
        const std::string name(key.str());
        if (name == "measure") {
            out.measures = text_list(node, path, "measure");
        } else if (name == "vary") {
            out.vary = text_list(node, path, "vary");
        } else if (name == "scenario") {
            auto s = node.value_exact<std::string>();
            if (!s) throw InputError(fmt::format("sweep file '{}': scenario must be a file name", path));
            // Relative to the sweep file, so that the pair can move together.
            out.scenario = beside(path, *s);
        } else if (const toml::table* t = node.as_table()) {
            for (const auto& [k, v] : *t) {
                const std::optional<std::string> value = as_text(v);
                if (!value)
                    throw InputError(fmt::format("sweep file '{}': [{}] {} must be a number or a string",
                                                 shown_text(path, 4096), shown_text(name),
                                                 shown_text(std::string(k.str()))));
                if (name == "fixed") out.fixed.emplace_back(std::string(k.str()), *value);
                else out.options.push_back({name, std::string(k.str()), *value});
            }
        } else {
            throw InputError(fmt::format("sweep file '{}': unknown key '{}' (allowed: measure, vary, scenario, "
                                         "[fixed] and a table of options per measure)", shown_text(path, 4096),
                                         shown_text(name)));
        }
    }
    return out;
}

}  // namespace dragon
