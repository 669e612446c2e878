// The open RunOutputs, as the file code reaches it (dragon/atomic_file.hpp has the class): where
// AtomicFile, RowLog and InputFile hand their files over while a run is open.
#pragma once

#include <sys/types.h>

#include <string>

#include "file_placement.hpp"

namespace dragon::run_outputs {

// Holds the placement until the run commits, if a run is open (and takes over `live_slot`, the
// source's entry for a kill's cleanup); false when none is, and the caller places it itself.
bool hold(const placement::Placement& p, int live_slot);

// An input the run reads (a file's device and inode, how messages name it); throws InputError
// if it is one of the run's outputs. Nothing when no run is open.
void note_input(dev_t dev, ino_t ino, const std::string& what, const std::string& path);
// An output the run will write, at `place` (the target, through its links); throws InputError
// if it is one of the inputs read so far. Nothing when no run is open.
void note_output(const std::string& target, const std::string& place);

}  // namespace dragon::run_outputs
