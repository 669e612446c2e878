// The contest workbooks read back by an independent reader (openpyxl) and compared with the
// contest's own templates; CSV and JSON tables parsed back.
#include <gtest/gtest.h>

#include "support/scratch.hpp"
#include "support/zip_entries.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <fmt/format.h>

#include "dragon/analyses.hpp"
#include "dragon/tables.hpp"

using namespace dragon;
namespace fs = std::filesystem;

namespace {

fs::path tmp_dir() { return dragon_test::scratch_dir(); }

// Writes (sheet,row,col,value) for a sample of cells, computed from the frames.
void sample_values(const std::vector<Frame>& frames, const fs::path& csv) {
    std::ofstream out(csv);
    std::mt19937 rng(5);
    const int n = static_cast<int>(frames.front().handles.size());
    for (int k = 0; k < 400; ++k) {
        const int col = static_cast<int>(rng() % frames.size());
        const int h = static_cast<int>(rng() % static_cast<unsigned>(n));
        const Handle& hd = frames[static_cast<size_t>(col)].handles[static_cast<size_t>(h)];
        out << fmt::format("位置,{},{},{:.6f}\n", 2 + 2 * h, col + 2, round6(hd.pos.x()));
        out << fmt::format("位置,{},{},{:.6f}\n", 3 + 2 * h, col + 2, round6(hd.pos.y()));
        out << fmt::format("速度,{},{},{:.6f}\n", 2 + h, col + 2, round6(hd.speed));
    }
}

int run_checker(const fs::path& written, const std::string& template_name, const fs::path& values) {
    const std::string cmd = fmt::format("/usr/bin/python3 {}/tests/tables/check_workbook.py '{}' '{}/{}' '{}'",
                                        DRAGON_SOURCE_DIR, written.string(), DRAGON_TEMPLATE_DIR, template_name,
                                        values.string());
    return std::system(cmd.c_str());
}

}  // namespace

TEST(Workbooks, Result1MatchesTheContestTemplate) {
    const Simulation sim(Scenario{});
    const auto frames = simulate_table(sim, 0.0, 300.0, 1.0);
    const fs::path out = tmp_dir() / "result1.xlsx", values = tmp_dir() / "result1-values.csv";
    write_result_xlsx(frames, out.string());
    sample_values(frames, values);
    EXPECT_EQ(run_checker(out, "result1-template.xlsx", values), 0);
}

TEST(Workbooks, Result4MatchesTheContestTemplate) {
    Scenario s;
    s.path.kind = PathKind::turnaround;
    const Simulation sim(s);
    const auto frames = simulate_table(sim, -100.0, 100.0, 1.0);
    const fs::path out = tmp_dir() / "result4.xlsx", values = tmp_dir() / "result4-values.csv";
    write_result_xlsx(frames, out.string());
    sample_values(frames, values);
    EXPECT_EQ(run_checker(out, "result4-template.xlsx", values), 0);
}

TEST(Workbooks, Result2MatchesTheContestTemplate) {
    const Frame f = Simulation(Scenario{}).frame(412.0);
    const fs::path out = tmp_dir() / "result2.xlsx", values = tmp_dir() / "result2-values.csv";
    write_result2_xlsx(f, out.string());
    std::ofstream v(values);
    for (size_t h = 0; h < f.handles.size(); h += 17) {
        v << fmt::format("Sheet1,{},2,{:.6f}\n", h + 2, round6(f.handles[h].pos.x()));
        v << fmt::format("Sheet1,{},3,{:.6f}\n", h + 2, round6(f.handles[h].pos.y()));
        v << fmt::format("Sheet1,{},4,{:.6f}\n", h + 2, round6(f.handles[h].speed));
    }
    v.close();
    EXPECT_EQ(run_checker(out, "result2-template.xlsx", values), 0);
}

// The library deflates at zlib's level 1 unless asked (WorkbookOptions): flag bits 11, as the
// tool's (tests/cli); zlib's default level 6 when asked for it: flag bits 00.
TEST(Workbooks, TheLibraryDeflatesAtTheLevelAsked) {
    for (const int level : {1, 6}) {
        const fs::path out = tmp_dir() / "level.xlsx";
        if (level == 1) write_result2_xlsx(Simulation(Scenario{}).frame(412.0), out.string());
        else write_result2_xlsx(Simulation(Scenario{}).frame(412.0), out.string(), WorkbookOptions{level});
        int deflated = 0;
        for (const auto& e : dragon_test::zip_entries(out)) {
            if (e.method != 8) continue;
            ++deflated;
            EXPECT_EQ(e.flags & 6, level == 1 ? 6 : 0) << e.name;
        }
        EXPECT_GT(deflated, 0);
    }
}

TEST(Tables, CsvRoundTrips) {
    const Simulation sim(Scenario{});
    const auto frames = simulate_table(sim, 10.0, 12.0, 0.5);
    const fs::path out = tmp_dir() / "t.csv";
    write_csv(frames, out.string());
    std::ifstream in(out);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "t,handle,x,y,speed");
    size_t rows = 0;
    while (std::getline(in, line)) {
        double t, x, y, v;
        int h;
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%d,%lf,%lf,%lf", &t, &h, &x, &y, &v), 5) << line;
        const Frame& f = frames[rows / 224];
        EXPECT_DOUBLE_EQ(t, f.time);
        EXPECT_NEAR(x, f.handles[static_cast<size_t>(h)].pos.x(), 5e-7);
        EXPECT_NEAR(y, f.handles[static_cast<size_t>(h)].pos.y(), 5e-7);
        EXPECT_NEAR(v, f.handles[static_cast<size_t>(h)].speed, 5e-7);
        ++rows;
    }
    EXPECT_EQ(rows, 5u * 224u);
    EXPECT_EQ(frames.back().time, 12.0);
}

TEST(Tables, LabelsAndTimes) {
    EXPECT_EQ(handle_label(0, 224), "龙头");
    EXPECT_EQ(handle_label(1, 224), "第1节龙身");
    EXPECT_EQ(handle_label(221, 224), "第221节龙身");
    EXPECT_EQ(handle_label(222, 224), "龙尾");
    EXPECT_EQ(handle_label(223, 224), "龙尾（后）");
    EXPECT_EQ(time_header(-100.0), "-100 s");
    EXPECT_EQ(time_header(0.1 + 0.2), "0.3 s");
    EXPECT_EQ(round6(-1e-9), 0.0);
    EXPECT_FALSE(std::signbit(round6(-1e-9)));
}

TEST(Tables, UnwritablePathLeavesNothing) {
    const Simulation sim(Scenario{});
    const auto frames = simulate_table(sim, 0.0, 1.0, 1.0);
    EXPECT_THROW(write_csv(frames, "/nonexistent-dir/x.csv"), InputError);
    EXPECT_THROW(write_table(frames, (tmp_dir() / "x.txt").string()), InputError);
    EXPECT_FALSE(fs::exists(tmp_dir() / "x.txt"));
    // No temporary files left beside the targets.
    for (const auto& e : fs::directory_iterator(tmp_dir()))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(Workbooks, TheLibraryRefusesMoreFramesThanASheetHolds) {
    // One column per frame and one for the labels: 16,383 frames fill a sheet; a library caller
    // asking for more gets an InputError, not a workbook cut short.
    std::vector<dragon::Frame> frames(dragon::kMaxWorkbookFrames + 1);
    const std::string path = (dragon_test::scratch_dir() / "too_wide.xlsx").string();
    try {
        dragon::write_result_xlsx(frames, path);
        ADD_FAILURE() << "a workbook of 16,384 frames was written";
    } catch (const dragon::InputError& e) {
        EXPECT_EQ(e.field(), "frame count");
        EXPECT_EQ(e.value(), "16384");
    }
    EXPECT_FALSE(std::filesystem::exists(path));
}
