// Reading a scenario file: the file's text, read as any TOML input is (dragon/input_file.hpp),
// then parsed by parse_scenario_toml. The only part of a scenario that touches a file.
#include "dragon/input_file.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

LoadedScenario read_scenario_file(const std::string& path, Scenario base) {
    return parse_scenario_toml(read_toml_input(path, "scenario file"), path, base);
}

Scenario load_scenario(const std::string& path, Scenario base) { return read_scenario_file(path, base).scenario; }

}  // namespace dragon
