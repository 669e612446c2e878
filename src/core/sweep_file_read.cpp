// Reading a sweep file: its text, read as any TOML input is (dragon/input_file.hpp), parsed by
// parse_sweep_file; its scenario file is named relative to the sweep file, so that the pair can
// move together.
#include <filesystem>

#include "dragon/input_file.hpp"
#include "dragon/sweep.hpp"

namespace dragon {

SweepFile read_sweep_file(const std::string& path) {
    SweepFile out = parse_sweep_file(read_toml_input(path, "sweep file"), path);
    if (!out.scenario.empty()) {
        const std::filesystem::path p(out.scenario);
        if (!p.is_absolute()) out.scenario = (std::filesystem::path(path).parent_path() / p).string();
    }
    return out;
}

}  // namespace dragon
