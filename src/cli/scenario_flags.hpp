// The scenario flags every subcommand shares. Precedence: flags over --scenario file over the
// contest defaults.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "dragon/scenario.hpp"

namespace dragon::cli {

class ScenarioFlags {
public:
    void add_to(CLI::App* sub);
    // The scenario these flags describe, validated (throws InputError).
    Scenario resolve() const;

private:
    std::string file_;
    std::string path_kind_;
    std::optional<double> pitch_, speed_, head_length_, body_length_, width_, hole_offset_;
    std::optional<double> start_turn_, turn_radius_, turn_pitch_, arc_ratio_;
    std::optional<long long> bench_count_;
};

}  // namespace dragon::cli
