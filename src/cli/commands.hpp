// The dragon CLI's subcommands. Each cmd_*.cpp registers one (or two) subcommands: it adds its
// options to the app and stores what to run once parsing has succeeded.
#pragma once

#include <functional>
#include <map>
#include <string>

#include <CLI/CLI.hpp>

namespace dragon::cli {

// Subcommand name -> what to run. A runner returns the exit code (0 on success); bad input is
// thrown as InputError and becomes exit 2.
using Registry = std::map<std::string, std::function<int()>>;

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

}  // namespace dragon::cli
