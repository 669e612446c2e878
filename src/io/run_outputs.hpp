// A RunOutputs as the file code reaches it (dragon/atomic_file.hpp has the class): where
// AtomicFile, RowLog, InputFile and make_output_folder hand their files over when they were
// given a run. Each function does nothing (or returns false) for a null run.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

#include "file_placement.hpp"
#include "dragon/atomic_file.hpp"

namespace dragon::run_outputs {

// Holds the placement until `run` commits, if there is a run (and takes over `live_slot`, the
// source's entry for a kill's cleanup); false when there is none, and the caller places it itself.
bool hold(RunOutputs* run, const placement::Placement& p, int live_slot);

// An input `run` reads (a file's device and inode, how messages name it); throws InputError
// if it is one of the run's outputs.
void note_input(RunOutputs* run, dev_t dev, ino_t ino, const std::string& what, const std::string& path);
// An output `run` will write, at `place` (the target, through its links); throws InputError
// if it is one of the inputs read so far.
void note_output(RunOutputs* run, const std::string& target, const std::string& place);
// Folders made for `run`'s outputs (outermost first): removed, if still empty, when it fails.
void note_folders(RunOutputs* run, const std::vector<std::string>& made);

}  // namespace dragon::run_outputs
