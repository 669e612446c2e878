// dragon sweep merge: the rows of a sweep's shards (or of any files that are parts of one sweep)
// joined into one file, checked to hold every scenario exactly once.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sweep_setup.hpp"

namespace dragon::cli {

// The whole sweep the files are parts of, from the first one's spec line (its shard 1/1). The
// first part is one of the inputs of `outputs`' run.
SweepSetup whole_sweep(const std::vector<std::string>& parts, RunOutputs* outputs);

// Writes the parts' rows, in the files' order, to `out` all-or-nothing. Throws InputError naming
// the file and the line at fault: a file of another sweep (its first line or header differs), a
// torn last line (an unfinished part: resume it first), a row that is no scenario of the sweep,
// a scenario twice (with the files it is in), or scenarios missing (how many, and the first).
// `on_row` hears every row. Returns the number of rows. The parts are inputs of `outputs`' run,
// and `out` one of its outputs.
std::size_t merge_parts(const SweepSetup& whole, const std::string& out, const std::vector<std::string>& parts,
                        const std::function<void(const std::string& csv_row)>& on_row, RunOutputs* outputs);

}  // namespace dragon::cli
