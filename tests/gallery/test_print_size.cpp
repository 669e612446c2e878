// Figures at print size: a figure made for a 3.5 in column is 3.5 in wide on the page and its
// text is set at the size asked, measured on the PDF by poppler (pdftotext's word boxes), not
// taken from the program's own report.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dragon/picture_size.hpp"
#include "gallery/figures.hpp"
#include "support/cli_run.hpp"
#include "support/scratch.hpp"

namespace dragon {
namespace {
namespace fs = std::filesystem;

struct Word {
    double x0, y0, x1, y1;
    std::string text;
};
struct PdfPage {
    double width = 0, height = 0;
    std::vector<Word> words;
};

// The page and its words (pdftotext -bbox: boxes in points).
PdfPage read_pdf(const fs::path& pdf) {
    const auto [ok, xml] = dragon_test::shell_output("pdftotext -bbox " + pdf.string() + " -");
    EXPECT_TRUE(ok) << xml;
    PdfPage page;
    std::smatch m;
    if (std::regex_search(xml, m, std::regex(R"re(<page width="([0-9.]+)" height="([0-9.]+)")re")))
        page.width = std::stod(m[1]), page.height = std::stod(m[2]);
    const std::regex word(R"re(<word xMin="([-0-9.]+)" yMin="([-0-9.]+)" xMax="([-0-9.]+)" yMax="([-0-9.]+)">([^<]*)</word>)re");
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), word); it != std::sregex_iterator(); ++it)
        page.words.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4]), (*it)[5]});
    return page;
}

bool ascii(const std::string& s) {
    for (unsigned char c : s)
        if (c >= 0x80) return false;
    return true;
}

// A word's box in poppler is the font's ascent plus descent across the line (1.164 em for
// DejaVu Sans: 0.928 + 0.236) and its advance along it. An axis name set upright (rotated a
// quarter turn) has them the other way round, so a word is set at `pt` points when either side
// of its box is that font box.
constexpr double kDejaVuBoxEm = 0.928 + 0.236;
bool set_at(const Word& w, double pt) {
    return std::abs(w.y1 - w.y0 - kDejaVuBoxEm * pt) < 0.02 || std::abs(w.x1 - w.x0 - kDejaVuBoxEm * pt) < 0.02;
}
double size_pt(const Word& w) { return (w.y1 - w.y0) / kDejaVuBoxEm; }

TEST(PrintSize, EveryFigureAtAColumnsWidthReadsAt8Points) {
    const fs::path dir = dragon_test::scratch_dir() / "column";
    FigureOptions fo;
    fo.asset_dir = std::string(DRAGON_SOURCE_DIR) + "/assets";  // the library reads no $DRAGON_ASSETS
    fo.format = "pdf";
    fo.print = print_preset("column");
    write_figures(dir.string(), Scenario{}, fo);
    for (const FigureInfo& f : figure_list()) {
        const PdfPage page = read_pdf(dir / (f.name + ".pdf"));
        EXPECT_NEAR(page.width, 3.5 * 72, 1e-6) << f.name;
        int body = 0;
        for (const Word& w : page.words) {
            if (!ascii(w.text)) continue;
            // The body size, or a fifth larger (titles); nothing smaller.
            EXPECT_TRUE(set_at(w, 8.0) || set_at(w, 1.2 * 8.0)) << f.name << ": '" << w.text << "' " << size_pt(w);
            body += set_at(w, 8.0);
            // Nothing runs off the page.
            EXPECT_GE(w.x0, -0.5) << f.name << ": '" << w.text << "'";
            EXPECT_LE(w.x1, page.width + 0.5) << f.name << ": '" << w.text << "'";
            EXPECT_GE(w.y0, -0.5) << f.name << ": '" << w.text << "'";
            EXPECT_LE(w.y1, page.height + 0.5) << f.name << ": '" << w.text << "'";
        }
        EXPECT_GT(body, 0) << f.name << ": no word at the body size";
    }
}

// Two words' boxes overlap (a little slack for the boxes' rounding).
bool overlap(const Word& a, const Word& b) {
    return std::min(a.x1, b.x1) - std::max(a.x0, b.x0) > 0.5 && std::min(a.y1, b.y1) - std::max(a.y0, b.y0) > 0.5;
}

TEST(PrintSize, NoTwoWordsOfAColumnFigureOverlap) {
    const fs::path dir = dragon_test::scratch_dir() / "overlap";
    FigureOptions fo;
    fo.asset_dir = std::string(DRAGON_SOURCE_DIR) + "/assets";  // the library reads no $DRAGON_ASSETS
    fo.format = "pdf";
    fo.print = print_preset("column");
    write_figures(dir.string(), Scenario{}, fo);
    for (const FigureInfo& f : figure_list()) {
        const PdfPage page = read_pdf(dir / (f.name + ".pdf"));
        for (std::size_t i = 0; i < page.words.size(); ++i)
            for (std::size_t j = i + 1; j < page.words.size(); ++j)
                EXPECT_FALSE(overlap(page.words[i], page.words[j]))
                    << f.name << ": '" << page.words[i].text << "' and '" << page.words[j].text << "'";
    }
}

// The pixels per metre a PNG states (its pHYs chunk), or 0.
std::uint32_t png_pixels_per_metre(const fs::path& png) {
    const std::string bytes = dragon_test::slurp(png);
    const std::size_t at = bytes.find("pHYs");
    if (at == std::string::npos || at + 8 > bytes.size()) return 0;
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + 4 + i]);
    return v;
}

TEST(PrintSize, RenderAtAPrintSizeSaysItsSizeInEveryFormat) {
    const fs::path dir = dragon_test::scratch_dir();
    // A PDF 8 cm wide, 4:3, text 9 pt.
    auto r = dragon_test::run_dragon("render --time 100 --size 800x600 --width-cm 8 --font-pt 9 -q -o " +
                                     (dir / "a.pdf").string());
    ASSERT_EQ(r.code, 0) << r.err;
    const PdfPage page = read_pdf(dir / "a.pdf");
    EXPECT_NEAR(page.width, 8 / 2.54 * 72, 1e-3);
    EXPECT_NEAR(page.height, 0.75 * 8 / 2.54 * 72, 0.5);  // whole pixels high
    ASSERT_FALSE(page.words.empty());
    // The scale bar's words at the body size, the annotation's a fifth larger.
    for (const Word& w : page.words)
        EXPECT_TRUE(set_at(w, 9.0) || set_at(w, 10.8)) << w.text << " " << size_pt(w);
    // An SVG of the same size in points.
    r = dragon_test::run_dragon("render --time 100 --size 800x600 --width-cm 8 -q -o " + (dir / "a.svg").string());
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string svg = dragon_test::slurp(dir / "a.svg");
    EXPECT_NE(svg.find(R"re(width="226.77)re"), std::string::npos) << svg.substr(0, 300);
    // A PNG at 600 dpi: 3.5 in is 2100 px, and the file says 600 dpi (23622 px per metre).
    r = dragon_test::run_dragon("render --time 100 --print column --dpi 600 -o " + (dir / "a.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("2100 x 2100 px at 600 dpi"), std::string::npos) << r.err;
    EXPECT_EQ(png_pixels_per_metre(dir / "a.png"), static_cast<std::uint32_t>(std::lround(600 / 0.0254)));
}

TEST(PrintSize, BadPrintSizesAreRefusedNamingTheFlag) {
    const fs::path out = dragon_test::scratch_dir() / "x.png";
    fs::remove(out);
    const struct {
        std::string args, says;
    } cases[] = {
        {"--print letter", "--print letter is not allowed: use column"},
        {"--width-in 0.5", "--width-in 0.5 is not allowed: give inches, 1..40"},
        {"--width-cm 200", "--width-cm 200 is not allowed: give centimetres, 2.54..101.6"},
        {"--font-pt 2", "--font-pt 2 is not allowed: give points, 4..36"},
        {"--dpi 5000", "--dpi 5000 is not allowed: give pixels per inch, 72..1200"},
        {"--width-in 40 --dpi 1200 --size 100x100", "would be 48000 x 48000 px"},
    };
    for (const auto& c : cases) {
        const auto r = dragon_test::run_dragon("render --time 1 " + c.args + " -o " + out.string());
        EXPECT_EQ(r.code, 2) << c.args;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << ": " << r.err;
        EXPECT_FALSE(fs::exists(out)) << c.args;
    }
    EXPECT_EQ(dragon_test::run_dragon("render --time 1 --width-in 3 --width-cm 8 -o " + out.string()).code, 2);
    EXPECT_EQ(dragon_test::run_dragon("figures --print column --scale 2 -o " + out.string()).code, 2);
}

}  // namespace
}  // namespace dragon

namespace dragon {
namespace {

// The gallery in Chinese: its words in the contest's terms, set in a font with CJK glyphs (the
// PDF embeds Noto Sans CJK beside DejaVu Sans), and the same numbers as in English.
TEST(ChineseFigures, WordsInChineseSetInACjkFont) {
    const std::filesystem::path dir = dragon_test::scratch_dir() / "zh";
    std::map<std::string, std::string> said;
    FigureOptions fo;
    fo.asset_dir = std::string(DRAGON_SOURCE_DIR) + "/assets";  // the library reads no $DRAGON_ASSETS
    fo.format = "pdf";
    fo.language = Language::zh;
    fo.only = {"fig4_first_contact", "plot_s_curve", "plot_speeds"};
    fo.on_text = [&](const std::string& figure, const std::string& text) { said[figure] += text + "\n"; };
    write_figures(dir.string(), Scenario{}, fo);
    EXPECT_NE(said["fig4_first_contact"].find("首次碰撞 t = 412.473838 s：第 1 节板凳碰到第 9 节"), std::string::npos)
        << said["fig4_first_contact"];
    EXPECT_NE(said["plot_s_curve"].find("调头空间"), std::string::npos) << said["plot_s_curve"];
    EXPECT_NE(said["plot_speeds"].find("把手"), std::string::npos) << said["plot_speeds"];
    for (const auto& [figure, text] : said) EXPECT_EQ(text.find("bench"), std::string::npos) << figure << ":\n" << text;
    const auto [ok, fonts] = dragon_test::shell_output("pdffonts " + (dir / "fig4_first_contact.pdf").string());
    ASSERT_TRUE(ok) << fonts;
    EXPECT_NE(fonts.find("NotoSansCJK"), std::string::npos) << fonts;
    EXPECT_NE(fonts.find("DejaVuSans"), std::string::npos) << fonts;
    const auto [text_ok, text] = dragon_test::shell_output("pdftotext " + (dir / "fig4_first_contact.pdf").string() + " -");
    ASSERT_TRUE(text_ok);
    EXPECT_NE(text.find("龙头"), std::string::npos) << text;  // the legend, as real text
}

}  // namespace
}  // namespace dragon
