// A row read back from a sweep's file (a resumed sweep's, a merge's parts) is checked whole
// before it is taken: a row cut short, one with cells added, a line of NULs or an edited cell
// would otherwise pass into a "finished" file and onto its map.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "dragon/row_files.hpp"
#include "dragon/sweep.hpp"
#include "dragon/sweep_setup.hpp"

namespace dragon {

// The longest cell a sweep writes is a status of a few notes, a few hundred characters: 4 KiB
// leaves room, and bounds a row by the number of its columns.
inline constexpr std::size_t kMaxCellBytes = 4096;

// How long a row of this sweep may be (a cell per column of its header, each kMaxCellBytes at
// most), for reading its files; `what` names such a file in messages.
RowFileLimits row_limits(const SweepSetup& setup, const std::string& what);

// The scenario a row holds, or what is wrong with it (without the file and the line, which the
// caller names):
//  - a control character (a NUL, a CR), or an unclosed quote;
//  - not one cell per column of the header;
//  - varied values that are no scenario of this sweep's part (its shard);
//  - a measure's cell that looks like a number, a list or an object (as a sweep writes them)
//    but does not read as one;
//  - a status that is neither "ok" nor a measure's note ("refused (collide): ..."), or that
//    does not match the cells: a measure without an answer must be noted as refused or failed,
//    and one noted so has no answer.
struct RowCheck {
    std::optional<std::size_t> index;  // the scenario, when the row is good
    std::string problem;               // else why not
    bool failed = false;               // a good row whose status notes a measure as failed
};
/// The check above of one row (a line of the file, without its line end) against this sweep.
RowCheck check_row(const SweepSetup& setup, const std::string& line);

}  // namespace dragon
