// Pictures for papers: a PDF that poppler reads, with the fonts embedded and the words
// extractable; SVG sizes in the pixels asked for.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "dragon/render.hpp"
#include "dragon/sweep_map.hpp"
#include "support/shell.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace dragon;

namespace {

std::pair<bool, std::string> run(const std::string& cmd) { return dragon_test::shell_output(cmd); }

std::string slurp(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

Scene annotated() {
    const Simulation sim(Scenario{});
    SceneOptions o;
    o.theme = load_theme("light", std::string(DRAGON_SOURCE_DIR) + "/assets");
    o.annotation = "Coiling in at t = 300 s";
    o.colour_by_speed = true;
    o.title_band = true;
    Scene s = make_scene(sim, sim.frame(300.0), o);
    s.labels.push_back({sim.frame(300.0).handles[0].pos, "head", o.theme.text, 13, 4, -4, 1, 1});
    return s;
}

TEST(Pdf, PopplerReadsItsPageItsFontsAndItsWords) {
    const fs::path pdf = dragon_test::scratch_dir() / "dragon.pdf";
    render_pdf(annotated(), 1600, 1200, pdf.string());
    const auto [info_ok, info] = run("pdfinfo " + pdf.string());
    ASSERT_TRUE(info_ok) << info;
    EXPECT_NE(info.find("Pages:           1"), std::string::npos) << info;
    // 1600 x 1200 CSS pixels at 96 to the inch: 1200 x 900 points.
    EXPECT_NE(info.find("Page size:       1200 x 900 pts"), std::string::npos) << info;
    const auto [fonts_ok, fonts] = run("pdffonts " + pdf.string());
    ASSERT_TRUE(fonts_ok) << fonts;
    EXPECT_NE(fonts.find("DejaVuSans"), std::string::npos) << fonts;
    // Every font line says "emb yes": the columns after the type are emb, sub, uni.
    std::istringstream lines(fonts);
    std::string line;
    int font_lines = 0;
    while (std::getline(lines, line))
        if (line.find("DejaVu") != std::string::npos) {
            ++font_lines;
            EXPECT_NE(line.find(" yes yes "), std::string::npos) << "not embedded as a subset: " << line;
        }
    EXPECT_GE(font_lines, 1);
    const auto [text_ok, text] = run("pdftotext " + pdf.string() + " -");
    ASSERT_TRUE(text_ok);
    for (const char* word : {"Coiling in at t = 300 s", "speed (m/s)", "head", "0.9995"})
        EXPECT_NE(text.find(word), std::string::npos) << word << " not in: " << text;
    // The scale bar's "2 m" (pdftotext may close up the narrow space between number and unit).
    EXPECT_TRUE(text.find("2 m") != std::string::npos || text.find("2m") != std::string::npos) << text;
}

TEST(Pdf, SvgIsSizedInThePixelsAskedFor) {
    const fs::path svg = dragon_test::scratch_dir() / "dragon.svg";
    render_svg(annotated(), 1600, 1200, svg.string());
    const std::string text = slurp(svg);
    EXPECT_NE(text.find("width=\"1600px\""), std::string::npos) << text.substr(0, 300);
    EXPECT_NE(text.find("height=\"1200px\""), std::string::npos) << text.substr(0, 300);
}


// A sweep's map for a paper: a PDF page with its axes' and panel's words in it; a picture
// format no surface writes is refused before anything is written.
TEST(Pdf, SweepMapsToo) {
    SweepMap map;
    map.x = {"bench width", "m", {0.2, 0.25, 0.3, 0.35}, 0.30};
    map.y = MapAxis{"body board length", "m", {1.8, 2.2, 2.6}, 2.2};
    MapPanel panel{"minimum pitch", "m", {}, {}};
    for (const double w : map.x.values)
        for (const double b : map.y->values) panel.values.push_back(w + 0.1 * b), panel.cells.push_back(MapCell::value);
    map.panels.push_back(panel);
    const fs::path pdf = dragon_test::scratch_dir() / "map.pdf";
    write_sweep_map(map, pdf.string());
    const auto [info_ok, info] = run("pdfinfo " + pdf.string());
    ASSERT_TRUE(info_ok) << info;
    std::istringstream lines(info);
    std::string key, pages;
    while (lines >> key && key != "Pages:") std::getline(lines, pages);
    lines >> pages;
    EXPECT_EQ(pages, "1") << info;
    const auto [ok, text] = run("pdftotext " + pdf.string() + " -");
    ASSERT_TRUE(ok);
    for (const char* word : {"bench width (m)", "body board length (m)", "minimum pitch"})
        EXPECT_NE(text.find(word), std::string::npos) << word << " not in: " << text;
    const fs::path jpg = dragon_test::scratch_dir() / "map.jpg";
    EXPECT_THROW(write_sweep_map(map, jpg.string()), InputError);
    EXPECT_FALSE(fs::exists(jpg));
}

}  // namespace
