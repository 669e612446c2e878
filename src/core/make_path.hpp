// Builds the path a scenario describes and where on it the head is at t = 0.
#pragma once

#include <memory>

#include "dragon/path.hpp"
#include "dragon/scenario.hpp"

namespace dragon {

struct PathBuild {
    std::shared_ptr<const Path> path;
    double start_arc = 0.0;  // head's arc position at t = 0
};

PathBuild make_path(const Scenario& s);

}  // namespace dragon
