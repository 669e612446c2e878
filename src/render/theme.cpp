// Themes from TOML files, and where the asset folder is.
#include <cctype>
#include <filesystem>
#include <map>
#include <new>
#include <optional>
#include <set>

#include <fontconfig/fontconfig.h>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dragon/input_file.hpp"
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
        throw InputError(fmt::format("{}: colour \"{}\" must be \"#rrggbb\" or \"#rrggbbaa\"", where, shown_text(text)));
    double c[4] = {0, 0, 0, 1};
    for (std::size_t i = 1, k = 0; i < text.size(); i += 2, ++k) {
        const int hi = hex_digit(text[i]), lo = hex_digit(text[i + 1]);
        if (hi < 0 || lo < 0)
            throw InputError(fmt::format("{}: colour \"{}\" has a non-hex digit", where, shown_text(text)));
        c[k] = (hi * 16 + lo) / 255.0;
    }
    return {c[0], c[1], c[2], c[3]};
}

// Generic families fontconfig resolves to whatever the system has: always there.
bool generic_family(const std::string& family) {
    static const std::set<std::string> generic = {"sans-serif", "sans", "serif", "monospace", "mono",
                                                  "cursive", "fantasy", "system-ui"};
    std::string lower;
    for (const char c : family) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return generic.count(lower) > 0;
}

// Whether fontconfig knows a font of this family (it would otherwise draw with a fallback,
// silently): one of the family names of the font it matches is the one asked for.
bool font_exists(const std::string& family) {
    if (generic_family(family)) return true;
    FcPattern* pattern = FcPatternCreate();
    if (!pattern) throw std::bad_alloc();
    FcPatternAddString(pattern, FC_FAMILY, reinterpret_cast<const FcChar8*>(family.c_str()));
    FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result = FcResultNoMatch;
    FcPattern* match = FcFontMatch(nullptr, pattern, &result);
    FcPatternDestroy(pattern);
    bool found = false;
    FcChar8* name = nullptr;
    for (int i = 0; match && !found && FcPatternGetString(match, FC_FAMILY, i, &name) == FcResultMatch; ++i)
        found = FcStrCmpIgnoreCase(name, reinterpret_cast<const FcChar8*>(family.c_str())) == 0;
    if (match) FcPatternDestroy(match);
    return found;
}

// A theme file: name and font at the top, colours in [colours]; anything else is refused, as in
// the other input files, so that a typo ([colour]) or the wrong file (a storyboard) is not
// silently the light theme. `check_font`: the font must be installed (a user's file; the
// assets' own themes name a font and fall back when it is missing).
Theme parse_theme(const fs::path& file, bool check_font, RunOutputs* outputs) {
    const std::string path = file.string();
    const std::string where = fmt::format("theme file '{}'", shown_text(path, 4096));
    const std::string text = read_toml_input(path, "theme file", outputs);
    toml::table doc;
    try {
        doc = toml::parse(text, path);
    } catch (const toml::parse_error& e) {
        throw InputError(fmt::format("{} is not valid TOML (line {}, column {}): {}", where, e.source().begin.line,
                                     e.source().begin.column, e.description()));
    }
    Theme t;
    for (const auto& [key, node] : doc) {
        const std::string k(key.str());
        if (k == "name" || k == "font") {
            const std::optional<std::string> v = node.value_exact<std::string>();
            if (!v) throw InputError(fmt::format("{}: {} must be a string", where, k));
            if (v->empty() || v->size() > 200)
                throw InputError(fmt::format("{}: {} \"{}\" is not allowed: give 1 to 200 characters", where, k,
                                             shown_text(*v)));
            (k == "name" ? t.name : t.font) = *v;
        } else if (k == "colours") {
            if (!node.is_table()) throw InputError(fmt::format("{}: colours must be a table: [colours]", where));
        } else if (node.is_table()) {
            throw InputError(fmt::format("{}: unknown section [{}] (allowed: [colours])", where, shown_text(k)));
        } else {
            throw InputError(fmt::format("{}: unknown key '{}' (allowed: name, font and the [colours] table)", where,
                                         shown_text(k)));
        }
    }
    if (check_font && !font_exists(t.font))
        throw InputError(fmt::format("{}: font \"{}\" is not installed (fc-list lists the fonts there are)", where,
                                     shown_text(t.font)));
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
                if (!arr || arr->size() < 2 || arr->size() > 256)
                    throw InputError(where + ": speed_ramp must be an array of 2 to 256 colours");
                t.speed_ramp.clear();
                for (const auto& c : *arr) {
                    auto s = c.value_exact<std::string>();
                    if (!s) throw InputError(where + ": speed_ramp entries must be strings");
                    t.speed_ramp.push_back(parse_colour(*s, where));
                }
                continue;
            }
            auto slot = slots.find(k);
            if (slot == slots.end())
                throw InputError(fmt::format("{}: unknown colour \"{}\"", where, shown_text(k)));
            auto s = node.value_exact<std::string>();
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
#ifdef DRAGON_INSTALL_ASSET_DIR
    if (consider(DRAGON_INSTALL_ASSET_DIR)) return DRAGON_INSTALL_ASSET_DIR;
#endif
    std::string list;
    for (const auto& p : tried) list += (list.empty() ? "" : ", ") + p.string();
    throw FileError(list.empty() ? "(none)" : list, "find the assets in",
                    "no folder there holds themes/ (name the assets folder; the dragon tool takes it from $DRAGON_ASSETS)");
}

Theme load_theme(const std::string& name_or_path, const std::string& asset_dir, RunOutputs* outputs) {
    const fs::path given(name_or_path);
    std::error_code ec;
    if (given.extension() == ".toml" || name_or_path.find('/') != std::string::npos) {
        if (fs::is_directory(given, ec))
            throw InputError(Key::theme, shown_text(name_or_path, 4096), "a folder: give a .toml file",
                             fmt::format("theme file '{}' is a folder: give a .toml file", shown_text(name_or_path, 4096)));
        return parse_theme(given, true, outputs);
    }
    const fs::path file = fs::path(find_asset_dir(asset_dir)) / "themes" / (name_or_path + ".toml");
    if (!fs::is_regular_file(file, ec)) {
        // A file of that name here is not read as a theme by its bare name: say how to name it.
        const bool here = fs::exists(fs::symlink_status(given, ec));
        const std::string allowed = fmt::format("use light, dark or a .toml file path{}",
                                                here ? fmt::format(" (the file here is ./{})", shown_text(name_or_path)) : "");
        throw InputError(Key::theme, shown_text(name_or_path), allowed,
                         fmt::format("theme \"{}\" is unknown: {}", shown_text(name_or_path), allowed));
    }
    return parse_theme(file, false, outputs);
}

}  // namespace dragon
