// The dragon CLI's subcommands. Each cmd_*.cpp registers one (or two) subcommands: it adds its
// options to the app and stores what to run once parsing has succeeded.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "dragon/executor.hpp"
#include "dragon/input_file.hpp"

namespace dragon::cli {

// What one run of the tool works with, made by main for the run and passed to its command:
// nothing of it is held anywhere else. The executor is the run's pool (one worker per core,
// joined when the run ends); every file the command reads or writes goes through `outputs`,
// put in place when the whole run has succeeded; `assets` is the folder of themes and presets
// (find_tool_assets).
struct ToolRun {
    Executor& executor;
    RunOutputs& outputs;
    std::string assets;
    // The "wrote FILE ..." lines, said by main once the outputs are in place (a run that fails
    // never says it wrote), unless the command was asked to be quiet.
    std::vector<std::string> wrote_lines;

    template <typename... A>
    void wrote(bool quiet, fmt::format_string<A...> f, A&&... args) {
        if (!quiet) wrote_lines.push_back(shown_text(fmt::format(f, std::forward<A>(args)...), 8192));
    }
};

// A command's run: the exit code (0 on success); bad input is thrown as InputError (exit 2).
using Runner = std::function<int(ToolRun&)>;

// Every command, as the registrations fill it in.
struct Registry {
    std::map<std::string, Runner> runners;  // the command's name -> its run
    // The command's name -> why the scenario flags it does not take are of no use to it, for
    // the command line's refusal of one ("" if it says nothing more).
    std::map<std::string, std::string> scenario_flags_unused;
};

void register_simulate(CLI::App& app, Registry& reg);
void register_solve(CLI::App& app, Registry& reg);
void register_collide(CLI::App& app, Registry& reg);
void register_min_pitch(CLI::App& app, Registry& reg);
void register_turnaround(CLI::App& app, Registry& reg);
void register_max_speed(CLI::App& app, Registry& reg);
void register_render(CLI::App& app, Registry& reg);
void register_figures(CLI::App& app, Registry& reg);
void register_video(CLI::App& app, Registry& reg);
void register_sweep(CLI::App& app, Registry& reg);
void register_film(CLI::App& app, Registry& reg);
void register_keys(CLI::App& app, Registry& reg);

}  // namespace dragon::cli
