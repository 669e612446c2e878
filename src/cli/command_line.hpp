// The command line as every subcommand shares it: `dragon help [COMMAND]`; an unknown command or
// option named, with the likely one meant; a scenario flag a command does not take named with
// the reason; an empty value ("--pitch ''") or a flag given a value ("--json=3") refused;
// CLI11's own errors as one line in the tool's words. Every refusal is one line on stderr and
// exit code 2.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace dragon::cli {

// Help as CLI11 writes it, less its lists of options that exclude or need others (the options'
// descriptions say so in words). Before the subcommands are added: they take the app's.
void use_help_formatter(CLI::App& app);

// Parses argv into `app` (its subcommands registered). Returns the exit code to end with
// (0 after printing help, 2 after one line on stderr), or nullopt: run the chosen subcommand.
// `scenario_flags_unused`: each command's reason for the scenario flags it does not take
// (Registry::scenario_flags_unused), said when one is given.
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv,
                                      const std::map<std::string, std::string>& scenario_flags_unused);

// The choice `word` most likely misspells or abbreviates: within two edits (and fewer than half
// its letters), or the only choice it starts (3 letters at least); "" if none.
std::string closest(const std::string& word, const std::vector<std::string>& choices);

}  // namespace dragon::cli
