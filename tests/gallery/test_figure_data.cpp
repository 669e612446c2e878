// figures --data: beside every figure, the numbers it draws as CSV with units in the header,
// each checked here against the library computed afresh (not against the program's output).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dragon/analyses.hpp"
#include "dragon/collision.hpp"
#include "dragon/turnaround.hpp"
#include "gallery/figures.hpp"
#include "support/scratch.hpp"

namespace dragon {
namespace {
namespace fs = std::filesystem;

using Table = std::vector<std::vector<std::string>>;

// A CSV of plain fields (the figures' data hold no quoted ones).
Table read_csv(const fs::path& p) {
    std::ifstream in(p);
    Table t;
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> row;
        std::stringstream ss(line);
        for (std::string f; std::getline(ss, f, ',');) row.push_back(f);
        if (!line.empty() && line.back() == ',') row.emplace_back();
        t.push_back(row);
    }
    return t;
}

double d(const std::string& s) { return std::strtod(s.c_str(), nullptr); }

class FigureData : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new fs::path(dragon_test::scratch_dir() / "data");
        FigureOptions fo;
        fo.asset_dir = std::string(DRAGON_SOURCE_DIR) + "/assets";  // the library reads no $DRAGON_ASSETS
        fo.scale = kMinFigureScale;
        fo.data = true;
        write_figures(dir_->string(), Scenario{}, fo);
    }
    static void TearDownTestSuite() { delete dir_; }
    static Table table(const std::string& name) { return read_csv(*dir_ / (name + ".csv")); }
    static fs::path* dir_;
};
fs::path* FigureData::dir_ = nullptr;

TEST_F(FigureData, EveryFigureHasItsNumbersWithUnits) {
    for (const FigureInfo& f : figure_list()) {
        const Table t = table(f.name);
        ASSERT_GE(t.size(), 2u) << f.name;
        bool unit = false;
        for (const std::string& h : t[0]) {
            EXPECT_FALSE(h.empty()) << f.name;
            unit = unit || h.find(" (") != std::string::npos;
        }
        EXPECT_TRUE(unit) << f.name << ": no column names its unit";
        for (const auto& row : t) EXPECT_EQ(row.size(), t[0].size()) << f.name;
    }
}

TEST_F(FigureData, SpeedsAndClearancesAreTheLibrarysAtTheirTimes) {
    const Simulation sim(Scenario{});
    const Table speeds = table("plot_speeds");
    ASSERT_EQ(speeds[0], (std::vector<std::string>{"t (s)", "handle", "speed (m/s)"}));
    ASSERT_EQ(speeds.size(), 1u + 6u * 224u);  // six moments, every handle
    for (std::size_t r = 1; r < speeds.size(); r += 97) {
        const Frame f = sim.frame(d(speeds[r][0]));
        EXPECT_EQ(d(speeds[r][2]), f.handles[std::stoul(speeds[r][1])].speed) << r;
    }
    const Table gaps = table("plot_clearance");
    ASSERT_EQ(gaps[0][1], "clearance (m)");
    for (std::size_t r = 1; r < gaps.size(); r += 53) {
        const Clearance c = clearance(sim.frame(d(gaps[r][0])));
        EXPECT_EQ(d(gaps[r][1]), c.distance) << r;
        EXPECT_EQ(std::stoi(gaps[r][2]), c.bench_a);
        EXPECT_EQ(std::stoi(gaps[r][3]), c.bench_b);
    }
    // The last sample is the first contact: the gap closed.
    EXPECT_LT(std::abs(d(gaps.back()[1])), 1e-6);
}

TEST_F(FigureData, TheTurnaroundsCurveAndRatioAreTheLibrarys) {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    const SCurve curve = design_s_curve(s);
    std::map<std::string, std::vector<std::string>> named;
    int arc_points = 0;
    for (const auto& row : table("plot_s_curve")) {
        if (row[1].empty()) named[row[0]] = row;
        arc_points += row[0] == "arc 1" || row[0] == "arc 2";
    }
    EXPECT_GT(arc_points, 100);
    EXPECT_EQ(d(named.at("A (entry)")[2]), curve.entry.x());
    EXPECT_EQ(d(named.at("A (entry)")[3]), curve.entry.y());
    EXPECT_EQ(d(named.at("B (exit)")[2]), curve.exit.x());
    EXPECT_EQ(d(named.at("C2 (centre of arc 2)")[3]), curve.c2.y());
    const Simulation sim(s);
    const Table ratio = table("plot_speed_ratio");
    for (std::size_t r = 1; r < ratio.size(); r += 211)
        EXPECT_EQ(d(ratio[r][1]), speed_ratio_at(sim.path(), s.bench, sim.head_arc(d(ratio[r][0]))).ratio) << r;
}

TEST_F(FigureData, ThePitchStatesAreEachPitchsOwnRun) {
    const Table t = table("fig5_pitch_states");
    ASSERT_EQ(t.size(), 7u);  // six pitches
    int touching = 0, clear = 0;
    for (std::size_t r = 1; r < t.size(); ++r) {
        const auto hit = contact_before_boundary(Scenario{}, d(t[r][0]));
        EXPECT_EQ(t[r][1] == "1", hit.has_value()) << t[r][0];
        if (hit) {
            ++touching;
            EXPECT_EQ(d(t[r][4]), hit->time);
            EXPECT_EQ(std::stoi(t[r][2]), hit->bench_a);
        } else {
            ++clear;
        }
    }
    EXPECT_GT(touching, 0);  // either side of the minimum pitch
    EXPECT_GT(clear, 0);
}

}  // namespace
}  // namespace dragon
