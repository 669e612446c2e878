// What a sweep's map says of each scenario, from the rows a real sweep wrote: the answer below
// and above min-pitch's range are two kinds of cell, a chain overlapping at the start collides
// (as min-pitch calls such a pitch), refused values are refused; the contest's dragon is marked
// only on a map that holds its scenario, at that scenario's values.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli/sweep_plot.hpp"
#include "cli/sweep_setup.hpp"
#include "sweep_support.hpp"

namespace fs = std::filesystem;
using namespace dragon;

namespace {

// The map of the rows `dragon sweep ARGS` writes, read back as --plot reads them.
SweepMap map_of(const std::string& args) {
    const fs::path out = dragon_test::scratch_dir() / "rows.csv";
    fs::remove(out);
    const dragon_test::CliRun r = dragon_test::run_dragon("sweep -q -o " + out.string() + " " + args);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    const std::vector<std::string> lines = sweep_test::lines(dragon_test::slurp(out));
    EXPECT_GE(lines.size(), 3u) << args;
    const SweepSetup setup = read_spec_line(lines.at(0), out.string());
    cli::MapCollector maps(setup);
    for (std::size_t k = 2; k < lines.size(); ++k) maps.add(lines[k]);
    return maps.map();
}

// The cell of the scenario at (x, y) of the axes' values.
MapCell cell_at(const SweepMap& m, double x, double y = NAN) {
    std::size_t ix = 0, iy = 0;
    while (ix < m.x.values.size() && std::abs(m.x.values[ix] - x) > 1e-12) ++ix;
    if (m.y)
        while (iy < m.y->values.size() && std::abs(m.y->values[iy] - y) > 1e-12) ++iy;
    EXPECT_LT(ix, m.x.values.size()) << x;
    return m.panels.at(0).cells.at(ix * (m.y ? m.y->values.size() : 1) + iy);
}

}  // namespace

TEST(SweepMapCells, BelowAndAboveTheRangeAreTwoKinds) {
    // --lo 0.36 --hi 0.5 (min-pitch on the command line, the same scenarios): at width 0.1 every
    // pitch from 0.36 m is collision-free (below the range); at width 0.35 in a 3 m turning space
    // none up to 0.5 m is (above it); at 0.4 the range starts at the width (refused).
    const SweepMap m = map_of("--vary width=0.1,0.35,0.4 --vary turn-radius=3,4.5 --measure min-pitch --lo 0.36 --hi 0.5");
    EXPECT_EQ(cell_at(m, 0.1, 4.5), MapCell::below_range);
    EXPECT_EQ(cell_at(m, 0.35, 3.0), MapCell::above_range);
    EXPECT_EQ(cell_at(m, 0.35, 4.5), MapCell::value);
    EXPECT_EQ(cell_at(m, 0.4, 4.5), MapCell::refused);
    const dragon_test::CliRun below = dragon_test::run_dragon("min-pitch --width 0.1 --lo 0.36 --hi 0.5 --json");
    EXPECT_TRUE(dragon_test::contains(below.out, "\"below_range\":true")) << below.out;
    const dragon_test::CliRun above =
        dragon_test::run_dragon("min-pitch --width 0.35 --turn-radius 3 --lo 0.36 --hi 0.5 --json");
    EXPECT_TRUE(dragon_test::contains(above.out, "\"above_range\":true")) << above.out;
    EXPECT_NE(m.panels[0].below_label, m.panels[0].above_label);
}

TEST(SweepMapCells, AChainOverlappingAtTheStartCollides) {
    // Pitch 0.35 m: benches 1 and 24 overlap at t = 0; min-pitch calls the pitch "collides", and
    // so does the collide map. Pitch 0.3 is the bench width: refused.
    const SweepMap m = map_of("--vary pitch=0.3,0.35,0.55 --measure collide");
    EXPECT_EQ(cell_at(m, 0.35), MapCell::overlapping);
    EXPECT_EQ(cell_at(m, 0.3), MapCell::refused);
    EXPECT_EQ(cell_at(m, 0.55), MapCell::value);
    const dragon_test::CliRun mp = dragon_test::run_dragon("min-pitch --lo 0.34 --hi 0.36 --grid 0.01");
    EXPECT_TRUE(dragon_test::contains(mp.out, "[0.3400000000, 0.3600000000] m  collides")) << mp.out;
}

TEST(SweepMapMark, OnlyOnTheContestsOwnScenario) {
    // Ratios 0.2, 0.575, ..., 3.2 pass by 2 without holding it: no mark; 0.5, 1, ..., 3 hold it.
    EXPECT_FALSE(map_of("--vary arc-ratio=0.2:3.2:9 --measure max-speed").x.mark.has_value());
    const SweepMap on = map_of("--vary arc-ratio=0.5:3:6 --measure max-speed");
    ASSERT_TRUE(on.x.mark.has_value());
    EXPECT_EQ(*on.x.mark, 2.0);
    // Two axes: both must hold the contest's value (body boards 2.2 m, width 0.3 m).
    const std::string two = " --vary width=0.25,0.3 --measure collide";
    EXPECT_FALSE(map_of("--vary body-length=1.6:2.8:8" + two).x.mark.has_value());
    const SweepMap grid = map_of("--vary body-length=1.6:2.8:7" + two);
    ASSERT_TRUE(grid.x.mark && grid.y && grid.y->mark);
    EXPECT_NEAR(*grid.x.mark, 2.2, 1e-12);
    EXPECT_NE(std::find(grid.x.values.begin(), grid.x.values.end(), *grid.x.mark), grid.x.values.end());
    EXPECT_EQ(*grid.y->mark, 0.3);
}
