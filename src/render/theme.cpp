// Themes from TOML files, and where the asset folder is.
#include <cstdlib>
#include <filesystem>
#include <map>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dragon/render.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

namespace fs = std::filesystem;

namespace {

bool holds_themes(const fs::path& dir) {
    std::error_code ec;
    return !dir.empty() && fs::is_directory(dir / "themes", ec);
}

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// "#rrggbb" or "#rrggbbaa".
Rgba parse_colour(const std::string& text, const std::string& where) {
    const bool ok_len = text.size() == 7 || text.size() == 9;
    if (!ok_len || text[0] != '#')
        throw InputError(fmt::format("{}: colour \"{}\" must be \"#rrggbb\" or \"#rrggbbaa\"", where, text));
    double c[4] = {0, 0, 0, 1};
    for (std::size_t i = 1, k = 0; i < text.size(); i += 2, ++k) {
        const int hi = hex_digit(text[i]), lo = hex_digit(text[i + 1]);
        if (hi < 0 || lo < 0)
            throw InputError(fmt::format("{}: colour \"{}\" has a non-hex digit", where, text));
        c[k] = (hi * 16 + lo) / 255.0;
    }
    return {c[0], c[1], c[2], c[3]};
}

Theme parse_theme(const fs::path& file) {
    toml::table doc;
    try {
        doc = toml::parse_file(file.string());
    } catch (const toml::parse_error& e) {
        throw InputError(fmt::format("theme {}: {} (line {})", file.string(), e.description(),
                                     e.source().begin.line));
    }
    Theme t;
    const std::string where = "theme " + file.string();
    if (auto v = doc["name"].value<std::string>()) t.name = *v;
    if (auto v = doc["font"].value<std::string>()) t.font = *v;
    const std::map<std::string, Rgba*> slots{
        {"background", &t.background}, {"text", &t.text},       {"grid", &t.grid},
        {"guide", &t.guide},           {"guide_out", &t.guide_out}, {"s_curve", &t.s_curve},
        {"turning_space", &t.turning_space}, {"turning_fill", &t.turning_fill},
        {"head", &t.head},             {"body", &t.body},       {"tail", &t.tail},
        {"outline", &t.outline},       {"handle", &t.handle},   {"highlight", &t.highlight},
        {"collision", &t.collision},   {"contact", &t.contact}};
    if (const toml::table* colours = doc["colours"].as_table()) {
        for (const auto& [key, node] : *colours) {
            const std::string k(key.str());
            if (k == "speed_ramp") {
                const toml::array* arr = node.as_array();
                if (!arr || arr->size() < 2)
                    throw InputError(where + ": speed_ramp must be an array of at least two colours");
                t.speed_ramp.clear();
                for (const auto& c : *arr) {
                    auto s = c.value<std::string>();
                    if (!s) throw InputError(where + ": speed_ramp entries must be strings");
                    t.speed_ramp.push_back(parse_colour(*s, where));
                }
                continue;
            }
            auto slot = slots.find(k);
            if (slot == slots.end())
                throw InputError(fmt::format("{}: unknown colour \"{}\"", where, k));
            auto s = node.value<std::string>();
            if (!s) throw InputError(fmt::format("{}: colour \"{}\" must be a string", where, k));
            *slot->second = parse_colour(*s, where);
        }
    }
    return t;
}

}  // namespace

std::string find_asset_dir(const std::string& hint) {
    std::vector<fs::path> tried;
    auto consider = [&](const fs::path& p) {
        tried.push_back(p);
        return holds_themes(p);
    };
    if (!hint.empty() && consider(hint)) return hint;
    if (const char* env = std::getenv("DRAGON_ASSETS"); env && *env && consider(env)) return env;
#ifdef DRAGON_INSTALL_ASSET_DIR
    if (consider(DRAGON_INSTALL_ASSET_DIR)) return DRAGON_INSTALL_ASSET_DIR;
#endif
    std::string list;
    for (const auto& p : tried) list += (list.empty() ? "" : ", ") + p.string();
    throw std::runtime_error("no asset folder with themes/ found (tried: " + list +
                             "); set DRAGON_ASSETS to the assets folder");
}

Theme load_theme(const std::string& name_or_path, const std::string& asset_dir) {
    const fs::path given(name_or_path);
    std::error_code ec;
    if (given.extension() == ".toml" || name_or_path.find('/') != std::string::npos) {
        if (fs::is_directory(given, ec))
            throw InputError(fmt::format("theme file {} is a folder: give a .toml file", name_or_path));
        if (!fs::is_regular_file(given, ec))
            throw InputError(fmt::format("theme file {} does not exist", name_or_path));
        return parse_theme(given);
    }
    const fs::path file = fs::path(find_asset_dir(asset_dir)) / "themes" / (name_or_path + ".toml");
    if (!fs::is_regular_file(file, ec))
        throw InputError(fmt::format("theme \"{}\" is unknown: use light, dark or a .toml file path",
                                     name_or_path));
    return parse_theme(file);
}

}  // namespace dragon
