// What dragon sweep was asked (its flags, then a sweep file under them), made into a sweep's
// setup (dragon/sweep_setup.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report.hpp"
#include "scenario_flags.hpp"
#include "dragon/sweep_setup.hpp"

namespace dragon::cli {

// What dragon sweep was asked, as text (the flags, then a sweep file under them).
struct SweepRequest {
    std::string file;                 // sweep file (TOML), or ""
    std::vector<std::string> vary;    // --vary, each NAME=VALUES
    std::vector<std::string> measures;
    std::optional<std::string> lo, hi;
    std::optional<double> grid, limit;
    std::optional<std::string> from, to;  // the window of collide, turnaround and max-speed
    std::string shard;                // "K/N", or "" for the whole sweep
};
// Throws InputError naming the flag or the file's key at fault: a bad --vary, an unknown or
// repeated measure, a measure that does not read a varied value, an option no measure takes, a
// fixed value that is also varied, a scenario flag no measure reads, a bad fixed value.
SweepSetup make_setup(const SweepRequest& request, ScenarioFlags& flags, RunOutputs* outputs);

}  // namespace dragon::cli
