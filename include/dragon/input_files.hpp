// The scenario and sweep files read from disk (the io component): each file read as an
// InputFile (a regular file, at most kMaxTomlBytes) and parsed by the core's parser of its text
// (parse_scenario_toml, parse_sweep_file). Given a RunOutputs, the file is one of that run's
// inputs, which none of its outputs may be.
#pragma once

#include <string>

#include "dragon/scenario.hpp"
#include "dragon/sweep.hpp"

namespace dragon {

class RunOutputs;  // dragon/atomic_file.hpp

// Reads a TOML scenario over `base` (missing keys keep base's values); throws InputError for an
// unreadable or malformed file (or a folder), an unknown section or key, or a value of the
// wrong type. Values are not range-checked here: validate() does that for those a computation
// reads.
LoadedScenario read_scenario_file(const std::string& path, Scenario base = {}, RunOutputs* outputs = nullptr);
// read_scenario_file(path, base, outputs).scenario.
Scenario load_scenario(const std::string& path, Scenario base = {}, RunOutputs* outputs = nullptr);

// Reads a sweep file; throws InputError naming the file and the key for an unreadable or
// malformed file, an unknown key, or a value of the wrong type.
SweepFile read_sweep_file(const std::string& path, RunOutputs* outputs = nullptr);

}  // namespace dragon
