#include "cli/command_line.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli/scenario_flags.hpp"
#include "dragon/input_file.hpp"

namespace dragon::cli {

namespace {

// Flags renamed since an earlier version: the new name, and what it is.
struct Renamed {
    const char* old_name;
    const char* new_name;
    const char* what;
};
constexpr Renamed kRenamed[] = {
    {"--body-count", "--bench-count", "benches in the chain, head and tail included"},
};

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), std::size_t{0});
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

std::vector<std::string> command_names(CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) names.push_back(sub->get_name());
    return names;
}

std::vector<std::string> option_names(const CLI::App& sub) {
    std::vector<std::string> names;
    for (const CLI::Option* opt : sub.get_options()) {
        for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
        for (const std::string& s : opt->get_snames()) names.push_back("-" + s);
    }
    return names;
}

// One line whatever the user typed: control characters in a value or a name are shown escaped.
void refuse(const std::string& line) {
    std::fputs(fmt::format("dragon: error: {}\n", shown_text(line, 2000)).c_str(), stderr);
}

bool looks_like_number(const std::string& s) {
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return end != s.c_str() && *end == '\0';
}

// Why an argument the subcommand left over is not one of its own.
std::string leftover_message(const CLI::App& sub, const std::vector<std::string>& extras) {
    const std::string cmd = sub.get_name();
    for (const std::string& arg : extras) {
        if (arg.size() < 2 || arg[0] != '-' || looks_like_number(arg)) continue;
        const std::string flag = arg.substr(0, arg.find('='));
        for (const Renamed& r : kRenamed)
            if (flag == r.old_name)
                return fmt::format("dragon {} has no option {}: it is now {} ({})", cmd, flag, r.new_name, r.what);
        if (std::string why = ScenarioFlags::not_taken(sub, flag); !why.empty()) return why;
        const std::string hint = closest(flag, option_names(sub));
        return fmt::format("dragon {} has no option {}{} (see dragon {} --help)", cmd, flag,
                           hint.empty() ? "" : fmt::format("; did you mean {}?", hint), cmd);
    }
    return fmt::format("unexpected argument '{}' for dragon {}: an option takes one value (see dragon {} --help)",
                       extras.front(), cmd, cmd);
}

// What to give instead of an empty value, by the option and its type.
std::string what_to_give(const CLI::App& sub, const CLI::Option& opt) {
    const std::string name = opt.get_name();
    const bool folder = sub.get_name() == "solve" || sub.get_name() == "figures";
    if (name == "--out") return folder ? "give a folder name" : "give a file name";
    if (name == "--scenario") return "give a .toml file";
    if (name == "--theme") return "use light, dark or a .toml file";
    if (name == "--path") return "use spiral or turnaround";
    const std::string type = opt.get_type_name();
    if (type.find("FLOAT") != std::string::npos || type.find("NUMBER") != std::string::npos) return "give a number";
    if (type.find("INT") != std::string::npos) return "give a whole number";
    return fmt::format("give a value (see dragon {} --help)", sub.get_name());
}

// An empty value ("--pitch ''", "-o ''", "--pitch="): CLI11 would take it as the default.
std::optional<std::string> empty_value(const CLI::App& sub) {
    for (const CLI::Option* opt : sub.get_options()) {
        if (opt->count() == 0) continue;
        for (const std::string& r : opt->results())
            if (r.empty()) return fmt::format("{} '' is not allowed: {}", opt->get_name(), what_to_give(sub, *opt));
    }
    return std::nullopt;
}

}  // namespace

std::string closest(const std::string& word, const std::vector<std::string>& choices) {
    std::string best;
    std::size_t best_distance = 3;  // two edits at most
    for (const std::string& c : choices) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_distance && 2 * d < word.size()) best_distance = d, best = c;
    }
    if (!best.empty() || word.size() < 3) return best;
    std::string prefix_of;
    for (const std::string& c : choices) {
        if (c.rfind(word, 0) != 0) continue;
        if (!prefix_of.empty()) return "";  // ambiguous
        prefix_of = c;
    }
    return prefix_of;
}

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
    const std::vector<std::string> names = command_names(app);
    const std::string list = fmt::format("{}", fmt::join(names, ", "));
    const auto unknown = [&](const std::string& word) {
        const std::string hint = closest(word, names);
        refuse(fmt::format("unknown command '{}'{}: the commands are {} (dragon --help describes them)", word,
                           hint.empty() ? "" : fmt::format(" (did you mean {}?)", hint), list));
        return 2;
    };
    if (argc < 2) {
        refuse(fmt::format("a command is needed: {} (dragon --help describes them)", list));
        return 2;
    }
    const std::string first = argv[1];
    if (first == "help") {
        if (argc == 2) {
            std::fputs(app.help().c_str(), stdout);
            return 0;
        }
        if (std::find(names.begin(), names.end(), argv[2]) == names.end()) return unknown(argv[2]);
        std::fputs(app.get_subcommand(argv[2])->help("dragon").c_str(), stdout);
        return 0;
    }
    if (!first.empty() && first[0] != '-' && std::find(names.begin(), names.end(), first) == names.end())
        return unknown(first);

    // "--pitch=": CLI11 would take the next argument as the value.
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.size() < 4 || arg.rfind("--", 0) != 0 || arg.back() != '=') continue;
        const CLI::App& sub = *app.get_subcommand(first);
        if (const CLI::Option* opt = sub.get_option_no_throw(arg.substr(0, arg.size() - 1))) {
            refuse(fmt::format("{} '' is not allowed: {}", opt->get_name(), what_to_give(sub, *opt)));
            return 2;
        }
    }
    // Leftover arguments are collected, not refused by CLI11, so that they can be named here
    // with what was meant.
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) sub->allow_extras();
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line, naming the bad value; CLI11's own exit codes are not ours.
        const bool known = std::find(names.begin(), names.end(), first) != names.end();
        refuse(fmt::format("{} (see dragon {}--help)", e.what(), known ? first + " " : ""));
        return 2;
    }
    const CLI::App& sub = *app.get_subcommands().front();
    if (!sub.remaining().empty()) {
        refuse(leftover_message(sub, sub.remaining()));
        return 2;
    }
    if (const std::optional<std::string> empty = empty_value(sub)) {
        refuse(*empty);
        return 2;
    }
    return std::nullopt;
}

}  // namespace dragon::cli
