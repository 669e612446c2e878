#include "command_line.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "scenario_flags.hpp"
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
std::string leftover_message(const CLI::App& sub, const std::vector<std::string>& extras,
                             const std::map<std::string, std::string>& scenario_flags_unused) {
    const std::string cmd = sub.get_name();
    for (const std::string& arg : extras) {
        if (arg.size() < 2 || arg[0] != '-' || looks_like_number(arg)) continue;
        const std::string flag = arg.substr(0, arg.find('='));
        for (const Renamed& r : kRenamed)
            if (flag == r.old_name)
                return fmt::format("dragon {} has no option {}: it is now {} ({})", cmd, flag, r.new_name, r.what);
        const auto reason = scenario_flags_unused.find(cmd);
        if (std::string why = ScenarioFlags::not_taken(sub, flag, reason == scenario_flags_unused.end() ? "" : reason->second);
            !why.empty())
            return why;
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
    if (name == "--size") return "give WIDTHxHEIGHT in pixels, as 1280x720";
    if (name == "--to" && sub.get_name() == "video")
        return "give a time in seconds (12.5), head travel in metres (100m), collision, boundary or end";
    if (opt.get_type_name() == "T|Xm")
        return "give a time in seconds (12.5, or 12.5s) or a length of the head's travel in metres (-100m)";
    if (name == "storyboard") return "give the storyboard's .toml file: dragon film STORY.toml -o FILM.mp4";
    const std::string type = opt.get_type_name();
    if (type.find("FLOAT") != std::string::npos || type.find("NUMBER") != std::string::npos) return "give a number";
    if (type.find("INT") != std::string::npos) return "give a whole number";
    return "give a value";
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

// The subcommand called `name`, if there is one.
const CLI::App* subcommand_named(CLI::App& app, const std::string& name) {
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
        if (sub->get_name() == name) return sub;
    return nullptr;
}

// The option of `sub` (or of one of its own subcommands, as sweep's merge) called `name`.
const CLI::Option* find_option(const CLI::App& sub, const std::string& name) {
    if (const CLI::Option* o = sub.get_option_no_throw(name)) return o;
    for (const CLI::App* inner : sub.get_subcommands([](const CLI::App*) { return true; }))
        if (const CLI::Option* o = inner->get_option_no_throw(name)) return o;
    return nullptr;
}

// A flag takes no value: "--json=3" would be taken as the flag given three times.
bool is_flag(const CLI::Option& opt) { return opt.get_expected_max() == 0; }

// "--pitch", or "the storyboard" for a positional argument.
std::string option_words(const CLI::Option& opt) {
    const std::string name = opt.get_name();
    return name.rfind("-", 0) == 0 ? name : "the " + name;
}

// The options of the command line's commands, in the order CLI11 runs their callbacks: the
// tool's own, then the command's, then those of the command's own subcommand (sweep merge).
std::vector<const CLI::Option*> options_in_order(const CLI::App& app) {
    std::vector<const CLI::Option*> out;
    for (const CLI::Option* opt : app.get_options()) out.push_back(opt);
    for (const CLI::App* sub : app.get_subcommands())  // the ones parsed
        for (const CLI::Option* opt : options_in_order(*sub)) out.push_back(opt);
    return out;
}

// Whether CLI11 takes `token` as an option's name rather than as a value: "-100m" and "-0.5"
// are values (no option of ours is one dash and a digit).
bool names_an_option(const std::string& token) {
    return token.size() > 1 && token[0] == '-' && !std::isdigit(static_cast<unsigned char>(token[1]));
}

// The option whose value is missing: one that takes a value, given last or followed by another
// option's name. Read from the arguments, since CLI11 stops parsing there.
const CLI::Option* missing_value(const CLI::App* sub, int argc, char** argv) {
    if (!sub) return nullptr;
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        if (!names_an_option(arg) || arg.find('=') != std::string::npos) continue;
        const CLI::Option* opt = find_option(*sub, arg);
        if (!opt || is_flag(*opt) || opt->get_expected_min() == 0) continue;
        if (i + 1 == argc || names_an_option(argv[i + 1])) return opt;
    }
    return nullptr;
}

// The parser's refusal in the tool's words, found from the parser's state rather than its
// sentences: the option that broke a rule (CLI11's options record what they were given and
// whether their conversion ran), the value, what to give. Anything not placed is passed on as
// CLI11 says it.
std::string parser_words(CLI::App& app, const std::string& first, const CLI::ParseError& e, int argc, char** argv) {
    const CLI::App* sub = subcommand_named(app, first);
    const std::vector<const CLI::Option*> options = options_in_order(app);
    const auto given = [](const CLI::Option* opt) { return opt->count() > 0; };
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
        if (const CLI::Option* opt = missing_value(sub, argc, argv))
            return fmt::format("{} needs a value: {}", opt->get_name(), what_to_give(*sub, *opt));
        for (const CLI::Option* opt : options) {
            const int most = opt->get_expected_max();
            if (is_flag(*opt) || most == CLI::detail::expected_max_vector_size) continue;
            if (opt->count() <= static_cast<std::size_t>(most)) continue;
            return most == 1 ? fmt::format("{} is given {} times: give it once", opt->get_name(), opt->count())
                             : fmt::format("{} is given {} values: give at most {}", opt->get_name(), opt->count(), most);
        }
    }
    if (dynamic_cast<const CLI::ConversionError*>(&e)) {
        // Callbacks run in order and stop at the one that failed: the last one run.
        const CLI::Option* failed = nullptr;
        for (const CLI::Option* opt : options)
            if (given(opt) && opt->get_callback_run()) failed = opt;
        if (failed && is_flag(*failed)) return fmt::format("{} takes no value: give it alone", failed->get_name());
        if (failed && sub)
            return fmt::format("{} {} is not allowed: {}", failed->get_name(), fmt::join(failed->results(), " "),
                               what_to_give(*sub, *failed));
    }
    if (dynamic_cast<const CLI::ExcludesError*>(&e)) {
        for (const CLI::Option* opt : options) {
            if (!given(opt)) continue;
            for (const CLI::Option* other : opt->get_excludes())
                if (given(other))
                    return fmt::format("{} and {} cannot be given together: give one of the two", opt->get_name(),
                                       other->get_name());
        }
    }
    if (dynamic_cast<const CLI::RequiredError*>(&e)) {
        if (!sub)
            return fmt::format("a command is needed first, then its options: {} (dragon --help describes them)",
                               fmt::join(command_names(app), ", "));
        for (const CLI::Option* opt : options)
            if (opt->get_required() && !given(opt))
                return fmt::format("{} is needed: {}", option_words(*opt), what_to_give(*sub, *opt));
    }
    return e.what();
}

}  // namespace

namespace {

// CLI11's help, without the "Excludes:" and "Needs:" lists it puts after an option's type (18
// lines of them in figures --help): each option's description says the rule in words instead
// ("takes no other option"), and a command line that breaks it is refused naming both options.
class HelpFormatter : public CLI::Formatter {
public:
    std::string make_option_opts(const CLI::Option* opt) const override {
        std::string out;
        if (opt->get_type_size() == 0) return out;
        if (!opt->get_type_name().empty()) out += " " + get_label(opt->get_type_name());
        if (!opt->get_default_str().empty()) out += "=" + opt->get_default_str();
        if (opt->get_expected_max() == CLI::detail::expected_max_vector_size) out += " ...";
        else if (opt->get_expected_min() > 1) out += fmt::format(" x {}", opt->get_expected());
        if (opt->get_required()) out += " " + get_label("REQUIRED");
        return out;
    }
};

}  // namespace

void use_help_formatter(CLI::App& app) { app.formatter(std::make_shared<HelpFormatter>()); }

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

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv,
                                      const std::map<std::string, std::string>& scenario_flags_unused) {
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
            refuse(is_flag(*opt) ? fmt::format("{} takes no value: give it alone", opt->get_name())
                                 : fmt::format("{} '' is not allowed: {}", opt->get_name(), what_to_give(sub, *opt)));
            return 2;
        }
    }
    // "--json=3": CLI11 would take a flag's value as how many times it was given.
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        const std::size_t eq = arg.find('=');
        if (arg.rfind("--", 0) != 0 || eq == std::string::npos || eq + 1 == arg.size()) continue;
        const CLI::App* sub = subcommand_named(app, first);
        const CLI::Option* opt = sub ? find_option(*sub, arg.substr(0, eq)) : nullptr;
        if (opt && is_flag(*opt)) {
            refuse(fmt::format("{} takes no value ('{}' given): give it alone", opt->get_name(), arg.substr(eq + 1)));
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
        refuse(fmt::format("{} (see dragon {}--help)", parser_words(app, known ? first : "", e, argc, argv), known ? first + " " : ""));
        return 2;
    }
    const CLI::App& sub = *app.get_subcommands().front();
    if (!sub.remaining().empty()) {
        refuse(leftover_message(sub, sub.remaining(), scenario_flags_unused));
        return 2;
    }
    if (const std::optional<std::string> empty = empty_value(sub)) {
        refuse(*empty);
        return 2;
    }
    return std::nullopt;
}

}  // namespace dragon::cli
