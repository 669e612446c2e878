// dragon keys: every value a user can set, from the library's one description (dragon/keys.hpp):
// its name in TOML files and Python (underscores), its flag and URL key (hyphens), its unit and
// what it means. docs/cli.md holds this table as the tool prints it.
#include <fmt/format.h>

#include "commands.hpp"
#include "error_words.hpp"
#include "report.hpp"
#include "dragon/json.hpp"
#include "dragon/keys.hpp"

namespace dragon::cli {

namespace {

struct KeysOptions {
    bool json = false;
};

// One row per spelling: keys that share a name (the three --crf scales, --size of a picture or
// a film) are one row, with the first one's meaning.
bool first_of_its_name(const KeyInfo& k) {
    for (const KeyInfo& other : all_keys()) {
        if (&other == &k) return true;
        if (other.name == k.name) return false;
    }
    return true;
}

}  // namespace

void register_keys(CLI::App& app, Registry& reg) {
    auto opt = std::make_shared<KeysOptions>();
    CLI::App* sub = app.add_subcommand("keys", "Every value a user can set: its TOML and Python name, flag, unit and meaning");
    sub->add_flag("--json", opt->json, "Print one JSON array on stdout");
    reg.runners["keys"] = [opt](ToolRun&) {
        Json rows = Json::array();
        if (!opt->json) fmt::print("{:<18} {:<18} {:<5} {}\n", "name", "flag", "unit", "meaning");
        for (const KeyInfo& k : all_keys()) {
            if (k.key == Key::none || !first_of_its_name(k)) continue;
            if (opt->json)
                rows.push_back({{"name", k.name}, {"flag", takes_flag(k.key) ? Json(flag_spelling(k.key)) : Json(nullptr)},
                                {"unit", k.unit}, {"words", k.words}, {"help", k.help}, {"scenario", k.scenario != 0}});
            else
                fmt::print("{:<18} {:<18} {:<5} {}\n", k.name,
                           takes_flag(k.key) ? flag_spelling(k.key) : std::string("-"),
                           k.unit.empty() ? "-" : k.unit, k.help);
        }
        if (opt->json) print_json(rows);
        return 0;
    };
}

}  // namespace dragon::cli
