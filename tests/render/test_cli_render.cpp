// dragon render and dragon figures end to end: files written whole, bad input exits 2 and
// leaves nothing behind.
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "support/scratch.hpp"

#include "dragon/cairo_handles.hpp"
#include "dragon/figures.hpp"

namespace {

namespace fs = std::filesystem;

int run(const std::string& args) {
    const std::string cmd = std::string(DRAGON_EXE) + " " + args + " > /dev/null 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class CliRender : public ::testing::Test {
protected:
    void SetUp() override {
        if (!fs::exists(DRAGON_EXE)) GTEST_SKIP() << "dragon is not built";
        dir = dragon_test::scratch_dir();
    }
    fs::path dir;
};

TEST_F(CliRender, PngAndSvgAtAGivenTime) {
    const auto png = dir / "t100.png", svg = dir / "t100.svg";
    ASSERT_EQ(run("render --time 100 --size 320x240 -o " + png.string()), 0);
    ASSERT_EQ(run("render --time 100 --size 320x240 --theme dark --speed-colours -o " + svg.string()), 0);
    dragon::cairo::Surface back(cairo_image_surface_create_from_png(png.c_str()));
    ASSERT_EQ(cairo_surface_status(back.get()), CAIRO_STATUS_SUCCESS);
    EXPECT_EQ(cairo_image_surface_get_width(back.get()), 320);
    EXPECT_EQ(cairo_image_surface_get_height(back.get()), 240);
    EXPECT_GT(fs::file_size(svg), 1000u);
}

TEST_F(CliRender, TurnaroundPathRenders) {
    const auto png = dir / "turn.png";
    EXPECT_EQ(run("render --path turnaround --time -20 --zoom 14 --size 200x200 -o " + png.string()), 0);
    EXPECT_TRUE(fs::exists(png));
}

TEST_F(CliRender, BadInputExitsTwoWithNoFile) {
    const auto out = dir / "bad.png";
    fs::remove(out);
    EXPECT_EQ(run("render --time 100 -o " + (dir / "bad.bmp").string()), 2);
    EXPECT_EQ(run("render -o " + out.string()), 2);                           // neither --time nor --collision
    EXPECT_EQ(run("render --time 100 --size 10x10 -o " + out.string()), 2);
    EXPECT_EQ(run("render --time 100 --theme sepia -o " + out.string()), 2);
    EXPECT_EQ(run("render --time 1e6 -o " + out.string()), 2);               // past the spiral's centre
    EXPECT_EQ(run("render --time 100 -o /no/such/dir/x.png"), 2);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(dir / "bad.bmp"));
}

TEST_F(CliRender, FiguresListAndOne) {
    EXPECT_EQ(run("figures --list"), 0);
    const auto figs = dir / "figs";
    ASSERT_EQ(run("figures --scale 0.5 --only plot_speeds plot_s_curve -o " + figs.string()), 0);
    EXPECT_TRUE(fs::exists(figs / "plot_speeds.png"));
    EXPECT_TRUE(fs::exists(figs / "plot_s_curve.png"));
    EXPECT_EQ(run("figures --only no_such_figure -o " + figs.string()), 2);
    // Every figure has its own file name.
    std::set<std::string> names;
    for (const auto& f : dragon::figure_list()) EXPECT_TRUE(names.insert(f.name).second) << f.name;
}

}  // namespace
