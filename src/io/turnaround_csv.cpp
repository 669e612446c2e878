#include "dragon/turnaround_csv.hpp"

#include "dragon/atomic_file.hpp"

namespace dragon {

void write_study_csv(const TurnaroundStudy& study, const std::string& path, RunOutputs* outputs) {
    AtomicFile file(path, outputs);
    write_text_file(file, study_csv(study));
    file.commit();
}

}  // namespace dragon
