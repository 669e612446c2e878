// dragon sweep --plot: the map of a sweep's rows, collected as the rows come (from a run, a
// resumed file or merged shards) and drawn through the render layer's sweep maps.
#pragma once

#include <string>
#include <vector>

#include "sweep_setup.hpp"
#include "dragon/sweep_map.hpp"

namespace dragon::cli {

// Throws InputError unless a map of this sweep can be drawn to `path`: a .png or .svg, and one
// or two axes with more than one value.
void check_plot(const SweepSetup& setup, const std::string& path);

class MapCollector {
public:
    explicit MapCollector(const SweepSetup& setup);
    // One row of the sweep's CSV (any order; each scenario once).
    void add(const std::string& csv_row);
    // The map of the rows added so far (scenarios without a row are shown as missing), its
    // words in `language`.
    SweepMap map(Language language = Language::en) const;

private:
    const SweepSetup& setup_;
    std::vector<std::size_t> plotted_;  // the axes the map shows: those with more than one value
    std::vector<std::string> header_;
    std::vector<std::vector<double>> values_;  // per measure, per map cell
    std::vector<std::vector<MapCell>> cells_;
};

}  // namespace dragon::cli
