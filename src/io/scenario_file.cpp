// A scenario file: read as an input, parsed by the core.
#include "dragon/input_file.hpp"
#include "dragon/input_files.hpp"

namespace dragon {

LoadedScenario read_scenario_file(const std::string& path, Scenario base, RunOutputs* outputs) {
    return parse_scenario_toml(read_toml_input(path, "scenario file", outputs), path, base);
}

Scenario load_scenario(const std::string& path, Scenario base, RunOutputs* outputs) {
    return read_scenario_file(path, base, outputs).scenario;
}

}  // namespace dragon
