// A scenario written as a file in today's form: what `dragon --scenario` and Python's
// Scenario.from_toml read back to the same values.
#include <fmt/format.h>

#include "dragon/scenario.hpp"
#include "dragon/sweep.hpp"

namespace dragon {

std::string scenario_toml(const Scenario& s) {
    std::string out = "# A scenario: one key a value, named as the key table names it (dragon/keys.hpp)\n";
    for (const KeyInfo& k : all_keys()) {
        if (!in_scenario_file(k.key)) continue;
        if (k.key == Key::path) {
            out += fmt::format("{} = \"{}\"\n", k.name, to_string(s.path.kind));
            continue;
        }
        const SweepParameter* p = find_sweep_parameter(hyphenated(k.key));
        // fmt's shortest form reads back to the same double; TOML reads 1e-05, inf and nan too.
        out += fmt::format("{} = {}\n", k.name, get_parameter(s, *p));
    }
    return out;
}

}  // namespace dragon
