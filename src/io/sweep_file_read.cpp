// A sweep file: read as an input, parsed by the core.
#include "dragon/input_file.hpp"
#include "dragon/input_files.hpp"

namespace dragon {

SweepFile read_sweep_file(const std::string& path, RunOutputs* outputs) {
    return parse_sweep_file(read_toml_input(path, "sweep file", outputs), path);
}

}  // namespace dragon
