// dragon render and dragon figures end to end: files written whole, bad input exits 2 and
// leaves nothing behind.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"
#include "support/scratch.hpp"

#include "render/cairo_handles.hpp"

namespace {

namespace fs = std::filesystem;

int run(const std::string& args) {
    const std::string cmd = std::string(DRAGON_EXE) + " " + args + " > /dev/null 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Captured {
    int code;
    std::string err;
};

// Runs dragon with stderr captured (stdout dropped).
Captured run_err(const std::string& args) {
    const fs::path err = dragon_test::scratch_dir() / "stderr.txt";
    const std::string cmd = std::string(DRAGON_EXE) + " " + args + " > /dev/null 2>" + err.string();
    const int status = std::system(cmd.c_str());
    std::ifstream in(err);
    std::stringstream ss;
    ss << in.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
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
    ASSERT_EQ(run("figures --scale 0.65 --only plot_speeds plot_s_curve -o " + figs.string()), 0);
    EXPECT_TRUE(fs::exists(figs / "plot_speeds.png"));
    EXPECT_TRUE(fs::exists(figs / "plot_s_curve.png"));
    EXPECT_EQ(run("figures --only no_such_figure -o " + figs.string()), 2);
}

// Views no one can mean: refused with exit code 2 and one line naming the value, no file.
TEST_F(CliRender, ViewsNoOneCanMeanAreRefused) {
    const auto out = dir / "view.png";
    struct Case {
        std::string args, word;
    };
    for (const Case& c : {Case{"--time 0 --zoom nan", "--zoom nan"}, Case{"--time 0 --zoom inf", "--zoom inf"},
                          Case{"--time 0 --zoom 0", "--zoom 0"}, Case{"--time 0 --zoom 1e-300", "--zoom 1e-300"},
                          Case{"--time 0 --zoom 1e300", "--zoom 1e+300"},
                          Case{"--time 0 --centre nan 0 --zoom 1", "--centre nan"},
                          Case{"--time 0 --centre 0 inf --zoom 1", "--centre 0 inf"},
                          Case{"--time 0 --centre 1e300 0 --zoom 1", "--centre 1e+300"},
                          // The head is 8.8 m out: a pixel of 1e-9 / 1600 m is finer than doubles
                          // resolve there (1.4e-8 m is the narrowest view).
                          Case{"--time 0 --zoom 1e-9", "use a zoom of 1.41e-08 or more"},
                          Case{"--collision --zoom 1e-9", "--zoom 1e-09"}}) {
        fs::remove(out);
        const Captured r = run_err("render " + c.args + " -o " + out.string());
        EXPECT_EQ(r.code, 2) << c.args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
        EXPECT_NE(r.err.find(c.word), std::string::npos) << c.args << ": " << r.err;
        EXPECT_FALSE(fs::exists(out)) << c.args;
    }
}

// Close-ups of any size are drawn, at the cost of what they show (the whole path flattened at
// the view's scale took 97 s and 9.8 GB for --zoom 1e-4, and never ended for smaller ones).
TEST_F(CliRender, CloseUpsDownToTheNarrowestViewAreDrawn) {
    for (const std::string zoom : {"1e-3", "1e-4", "1e-6", "2e-8"}) {
        const auto png = dir / ("zoom" + zoom + ".png");
        EXPECT_EQ(run("render --time 0 --size 400x400 --zoom " + zoom + " -o " + png.string()), 0) << zoom;
        EXPECT_TRUE(fs::exists(png)) << zoom;
    }
    EXPECT_EQ(run("render --collision --size 400x400 --zoom 1e-6 -o " + (dir / "contact.svg").string()), 0);
}

// The command line's way to the same: a close-up of the contact for a paper, with its legend
// and the inset of the whole dragon.
TEST(Pdf, RenderWritesAPdfWithItsLegend) {
    const fs::path pdf = dragon_test::scratch_dir() / "contact.pdf";
    const auto r = dragon_test::run_dragon("render --collision --zoom 3 --legend --inset --size 800x600 -q -o " +
                                           pdf.string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto [ok, text] = dragon_test::shell_output("pdftotext " + pdf.string() + " -");
    ASSERT_TRUE(ok);
    for (const char* word : {"first contact t = 412.473838 s: benches 1 and 9", "touching benches", "tail"})
        EXPECT_NE(text.find(word), std::string::npos) << word << " not in: " << text;
    const auto bad = dragon_test::run_dragon("render --time 1 -o " + (dragon_test::scratch_dir() / "x.eps").string());
    EXPECT_EQ(bad.code, 2);
    EXPECT_TRUE(dragon_test::contains(bad.err, "use .png, .svg or .pdf")) << bad.err;
}

}  // namespace
