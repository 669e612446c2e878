// The layout check: every kind of picture the tool draws (the gallery, stills, sweep maps, film
// frames), in English and Chinese, at every print size and at the smallest sizes accepted, run
// in-process through the tool's own commands with the renderer's layout log on (render/paint.hpp:
// every line of text, legend and mark it placed, in the page's units). On every picture:
//   - no text leaves the page, nor the clip it is drawn in (a plot's frame, a panel);
//   - no text overlaps another;
//   - a legend covers no mark it explains (a touching bench, a plotted point) and no text of
//     its picture but its own;
//   - no text is under the floor the docs give: at a print size the body size asked (pt on a PDF
//     page); on screen a 13 px label at kMinTextPx (11 px) at least, so the smallest text, tick
//     numbers (11 px at 800 px), at 11 * 11 / 13 = 9.3 px;
//   - a page-size picture fits a text block: at most 648 pt tall (US letter less 1 in margins;
//     A4 less 2.5 cm is 700 pt).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cli/asset_dir.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/render.hpp"
#include "gallery/figures.hpp"
#include "render/paint.hpp"
#include "support/scratch.hpp"

namespace {

using dragon::render::LayoutItem;

// One picture's placements.
struct Picture {
    LayoutItem page;
    std::vector<LayoutItem> items;
};

// Runs `dragon ARGS` in this process (the tool's own parsing and commands) with the layout log
// on; the pictures it drew. Outputs go to the test's scratch folder and are discarded.
std::vector<Picture> drawn_by(const std::string& args) {
    CLI::App app{"dragon"};
    app.name("dragon");
    app.require_subcommand(1);
    dragon::cli::Registry reg;
    dragon::cli::register_render(app, reg);
    dragon::cli::register_figures(app, reg);
    dragon::cli::register_film(app, reg);
    dragon::cli::register_sweep(app, reg);
    std::vector<std::string> words{"dragon"};
    std::istringstream in(args);
    for (std::string w; in >> w;) words.push_back(w);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    EXPECT_FALSE(dragon::cli::parse_command_line(app, static_cast<int>(argv.size()), argv.data(), reg.scenario_flags_unused)) << args;
    dragon::render::LayoutRecording log;
    {
        dragon::RunOutputs outputs;  // nothing is put in place: the files are not the point
        dragon::InlineExecutor here;  // every picture drawn on this thread, where the log records
        // The assets as the tool's main finds them: its copy beside this build's bin folders.
        dragon::cli::ToolRun run{here, outputs, dragon::cli::find_tool_assets(nullptr), {}};
        EXPECT_EQ(reg.runners.at(app.get_subcommands().front()->get_name())(run), 0) << args;
    }
    std::vector<Picture> out;
    for (const LayoutItem& p : log.placed()) {
        if (p.kind == LayoutItem::Kind::picture) {
            if (p.x1 <= 2 && p.y1 <= 2) continue;  // a scratch surface for measuring
            out.push_back({p, {}});
        } else if (!out.empty()) {
            out.back().items.push_back(p);
        }
    }
    return out;
}

bool overlap(const LayoutItem& a, const LayoutItem& b, double by) {
    return std::min(a.x1, b.x1) - std::max(a.x0, b.x0) > by && std::min(a.y1, b.y1) - std::max(a.y0, b.y0) > by;
}
bool inside(const LayoutItem& a, const LayoutItem& box, double slack) {
    return a.x0 >= box.x0 - slack && a.x1 <= box.x1 + slack && a.y0 >= box.y0 - slack && a.y1 <= box.y1 + slack;
}
std::string where(const LayoutItem& p) {
    return fmt::format("'{}' [{:.1f},{:.1f}]-[{:.1f},{:.1f}]", p.text, p.x0, p.y0, p.x1, p.y1);
}

// What is wrong with one picture, a line each ("" when nothing). `floor`: the smallest text
// allowed, in the page's units; `max_height`: the tallest page allowed (0: any).
std::vector<std::string> faults(const Picture& pic, double floor, double max_height) {
    std::vector<std::string> out;
    const LayoutItem& page = pic.page;
    // Half a point (or pixel) of slack: a glyph's advance is not its ink.
    const double slack = 0.5;
    if (max_height > 0 && page.y1 > max_height)
        out.push_back(fmt::format("the page is {:.0f} x {:.0f}, taller than a text block ({:.0f})", page.x1, page.y1,
                                  max_height));
    std::vector<const LayoutItem*> texts, legends, marks;
    for (const LayoutItem& p : pic.items)
        (p.kind == LayoutItem::Kind::text ? texts : p.kind == LayoutItem::Kind::legend ? legends : marks).push_back(&p);
    if (texts.empty()) out.push_back("no text was recorded");
    for (const LayoutItem* t : texts) {
        if (!inside(*t, page, slack)) out.push_back("off the page: " + where(*t));
        else if (t->clipped) out.push_back("cut by the clip it is drawn in: " + where(*t));
        if (t->size < floor * (1 - 1e-6))
            out.push_back(fmt::format("under the floor ({:.2f} < {:.2f}): {}", t->size, floor, where(*t)));
    }
    for (std::size_t i = 0; i < texts.size(); ++i)
        for (std::size_t j = i + 1; j < texts.size(); ++j)
            if (overlap(*texts[i], *texts[j], slack)) out.push_back("overlap: " + where(*texts[i]) + " and " + where(*texts[j]));
    for (const LayoutItem* l : legends) {
        for (const LayoutItem* m : marks)  // a mark may be a point: any part of it under the legend
            if (m->x1 > l->x0 && m->x0 < l->x1 && m->y1 > l->y0 && m->y0 < l->y1)
                out.push_back("the legend " + where(*l) + " covers the mark " + where(*m));
        for (const LayoutItem* t : texts)
            if (overlap(*l, *t, slack) && !inside(*t, *l, slack))
                out.push_back("the legend " + where(*l) + " covers the text " + where(*t));
    }
    return out;
}

struct Case {
    std::string name;
    std::string args;  // the command, without -o
    std::string out;   // the output's name in the scratch folder (a file, or a folder)
    double floor;      // smallest text, page units
    double max_height = 0;
};

// On screen: the tick numbers' size when a 13 px label is at kMinTextPx.
constexpr double kScreenFloor = dragon::kMinTextPx * 11.0 / 13.0;

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }
void PrintTo(const Case& c, std::ostream* os) { *os << c.args; }

class Layout : public ::testing::TestWithParam<Case> {};

TEST_P(Layout, FitsTheFrameNothingOverlapsNothingUnderTheFloor) {
    const Case& c = GetParam();
    const std::filesystem::path dir = dragon_test::fresh_dir("out");
    std::string args = c.args;
    if (const auto at = args.find("PLOT"); at != std::string::npos) args.replace(at, 4, (dir / "map").string());
    const std::vector<Picture> pictures = drawn_by(args + " -o " + (dir / c.out).string());
    ASSERT_FALSE(pictures.empty()) << c.args;
    std::string report;
    int bad = 0;
    for (std::size_t i = 0; i < pictures.size(); ++i) {
        const std::vector<std::string> f = faults(pictures[i], c.floor, c.max_height);
        if (f.empty()) continue;
        ++bad;
        report += fmt::format("\n picture {} of {} ({:.0f} x {:.0f}):", i + 1, pictures.size(), pictures[i].page.x1,
                              pictures[i].page.y1);
        for (std::size_t k = 0; k < f.size() && k < 8; ++k) report += "\n   " + f[k];
        if (f.size() > 8) report += fmt::format("\n   ... and {} more", f.size() - 8);
    }
    EXPECT_EQ(bad, 0) << c.args << report;
}

// Print sizes: the body text in points, as a PDF page holds it; a page-wide figure fits a text
// block (US letter with 1 in margins: 9 in tall).
constexpr double kTextBlockPt = 648.0;
struct PrintSizeCase {
    const char* flag;
    double pt;
};
constexpr PrintSizeCase kPrint[] = {{"column", 8.0}, {"page", 9.0}, {"a4", 10.5}};

std::vector<Case> cases() {
    std::vector<Case> out;
    for (const char* lang : {"en", "zh"}) {
        const std::string L = std::string("--lang ") + lang;
        // The gallery: on screen at its own size and at the smallest scale, and at every print size.
        out.push_back({fmt::format("figures_{}_screen", lang), "figures " + L, "g", kScreenFloor});
        out.push_back({fmt::format("figures_{}_smallest_scale", lang),
                       fmt::format("figures --scale {} {}", dragon::kMinFigureScale, L), "g", kScreenFloor});
        for (const auto& p : kPrint)
            out.push_back({fmt::format("figures_{}_{}", lang, p.flag), fmt::format("figures --format pdf --print {} {}", p.flag, L),
                           "g", p.pt, kTextBlockPt});
        // Stills: the contact close-up with its legend and inset, the whole dragon by speed.
        const std::string contact = "render --collision --zoom 3 --legend --inset " + L;
        out.push_back({fmt::format("contact_{}_screen", lang), contact, "c.png", kScreenFloor});
        out.push_back({fmt::format("contact_{}_320x240", lang), contact + " --size 320x240", "c.png", kScreenFloor});
        for (const auto& p : kPrint)
            out.push_back({fmt::format("contact_{}_{}", lang, p.flag), contact + " --print " + p.flag, "c.pdf", p.pt, kTextBlockPt});
        const std::string whole = "render --time 300 --speed-colours --legend " + L;
        out.push_back({fmt::format("speeds_{}_320x240", lang), whole + " --size 320x240", "s.png", kScreenFloor});
        out.push_back({fmt::format("speeds_{}_column", lang), whole + " --print column", "s.pdf", 8.0, kTextBlockPt});
        // Sweep maps: a heat map, and a line plot with a refused value.
        // (The contest's dragon in the middle of the map: at a column's width its label has room
        // on neither side of the mark.)
        const std::string heat = "sweep --vary width=0.2,0.3,0.4 --vary body-length=1.6,2.2,2.8 --measure min-pitch "
                                 "--lo width+0.09 --hi width+0.25 --grid 0.01 -q " + L;
        out.push_back({fmt::format("heat_map_{}_screen", lang), heat + " --plot PLOT.png", "h.csv", kScreenFloor});
        for (const auto& p : kPrint)
            out.push_back({fmt::format("heat_map_{}_{}", lang, p.flag), heat + " --plot PLOT.pdf --print " + p.flag, "h.csv",
                           p.pt, kTextBlockPt});
        const std::string line = "sweep --vary arc-ratio=-1,1.5,2,2.5 --measure max-speed -q " + L;
        out.push_back({fmt::format("line_plot_{}_screen", lang), line + " --plot PLOT.png", "l.csv", kScreenFloor});
        out.push_back({fmt::format("line_plot_{}_column", lang), line + " --plot PLOT.pdf --print column", "l.csv", 8.0,
                       kTextBlockPt});
        // Film frames: the first contact's caption at the smallest film size the docs show, and
        // a poster at a column's width.
        const std::string film = fmt::format("film {}/assets/films/contest.toml ", DRAGON_SOURCE_DIR);
        for (const char* at : {"27", "45", "63"}) {
            out.push_back({fmt::format("film_{}s_{}_320x180", at, lang), film + "--at " + at + " --size 320x180 --lang " + lang,
                           "f.png", kScreenFloor});
            out.push_back({fmt::format("film_{}s_{}_1280x720", at, lang), film + "--at " + at + " --lang " + lang, "f.png",
                           kScreenFloor});
        }
        out.push_back({fmt::format("film_27s_{}_column", lang), film + "--at 27 --print column --lang " + lang, "f.png",
                       8.0 * 300 / 72});
    }
    return out;
}

INSTANTIATE_TEST_SUITE_P(EveryFigure, Layout, ::testing::ValuesIn(cases()), case_name);

// A refused value (an arc ratio of -1) sets no axis: the line plot's ticks, as placed, stay
// within the values that ran (1.5 to 2.5), none of them negative.
TEST(LayoutOfASweep, ARefusedValueSetsNoAxis) {
    const std::filesystem::path dir = dragon_test::fresh_dir("out");
    const std::vector<Picture> pictures =
        drawn_by("sweep --vary arc-ratio=-1,1.5,2,2.5 --measure max-speed -q --plot " + (dir / "m.png").string() + " -o " +
                 (dir / "m.csv").string());
    ASSERT_EQ(pictures.size(), 1u);
    int ticks = 0;
    for (const LayoutItem& t : pictures[0].items) {
        if (t.kind != LayoutItem::Kind::text) continue;
        EXPECT_FALSE(t.text.starts_with("\u2212")) << "a negative tick: " << t.text;
        ticks += t.text.starts_with("1.") || t.text.starts_with("2.");
    }
    EXPECT_GE(ticks, 2);
}

}  // namespace
