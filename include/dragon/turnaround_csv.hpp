// Q4's study written to a file (the io component); its text is the core's study_csv.
#pragma once

#include <string>

#include "dragon/turnaround.hpp"

namespace dragon {

class RunOutputs;  // dragon/atomic_file.hpp

// study_csv(study) written all-or-nothing to `path` (an AtomicFile, one of `outputs`' files if
// given). Throws InputError for a path that cannot be written, FileError for a failed write.
void write_study_csv(const TurnaroundStudy& study, const std::string& path, RunOutputs* outputs = nullptr);

}  // namespace dragon
