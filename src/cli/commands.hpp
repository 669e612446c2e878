// The dragon CLI's subcommands. Each cmd_*.cpp registers one (or two) subcommands: it adds its
// options to the app and stores what to run once parsing has succeeded.
#pragma once

#include <functional>
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "dragon/atomic_file.hpp"
#include "dragon/executor.hpp"

namespace dragon::cli {

// Subcommand name -> what to run, on the run's executor (the tool's pool, one worker per core,
// made once the command line is read and joined when the run ends) and with the run's outputs
// (main's RunOutputs: every file the command reads or writes goes through it, put in place when
// the whole run has succeeded). A runner returns the exit code (0 on success); bad input is
// thrown as InputError and becomes exit 2.
using Registry = std::map<std::string, std::function<int(Executor&, RunOutputs&)>>;

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
