// The gallery (the tool's, not the library's) for any scenario: its figures carry that scenario's own numbers, computed here
// from the library's answers; remarks about the contest's paper appear only for the contest's
// own dragon; a run without a contact says so.
#include <filesystem>
#include <map>
#include <set>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dragon/analyses.hpp"
#include "dragon/input_files.hpp"
#include "dragon/render.hpp"
#include "gallery/figures.hpp"
#include "support/cli_run.hpp"
#include "support/scratch.hpp"

namespace dragon {
namespace {

// Every text each figure put on its picture, one per line, by figure.
std::map<std::string, std::string> figure_texts(const Scenario& s, const std::vector<std::string>& only) {
    std::map<std::string, std::string> said;
    FigureOptions o;
    o.asset_dir = std::string(DRAGON_SOURCE_DIR) + "/assets";  // the library reads no $DRAGON_ASSETS
    o.scale = kMinFigureScale;  // small pictures: the texts are the same
    o.only = only;
    o.on_text = [&](const std::string& figure, const std::string& text) { said[figure] += text + "\n"; };
    write_figures(dragon_test::scratch_dir().string(), s, o);
    return said;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void expect_no_paper_remark(const std::map<std::string, std::string>& said) {
    for (const auto& [figure, text] : said)
        for (const char* remark : {"paper", "413", "0.42 m"}) EXPECT_FALSE(has(text, remark)) << figure << ":\n" << text;
}

// The issue's example: 100 benches 0.25 m wide. They touch at 422.64 s, not the contest's
// 412.47 s, and their minimum pitch is their own.
TEST(Figures, AnotherScenarioCarriesItsOwnNumbers) {
    Scenario s;
    s.bench.bench_count = 100;
    s.bench.width = 0.25;
    const auto said = figure_texts(s, {"fig4_first_contact", "fig5_pitch_states", "plot_clearance", "plot_speeds",
                                       "fig2_dragon_300s"});
    ASSERT_EQ(said.size(), 5u);
    expect_no_paper_remark(said);

    const Simulation sim(s);
    const std::optional<Contact> hit = first_contact(sim, 0.0, sim.valid_end());
    ASSERT_TRUE(hit);
    const std::string when = fmt::format("{:.6f}", hit->time);
    EXPECT_TRUE(has(said.at("plot_clearance"), "First contact at t = " + when)) << said.at("plot_clearance");
    EXPECT_TRUE(has(said.at("fig4_first_contact"),
                    fmt::format("First contact at t = {} s: bench {} touches bench {}", when, hit->bench_a, hit->bench_b)))
        << said.at("fig4_first_contact");
    EXPECT_TRUE(has(said.at("plot_speeds"), "100 = tail rear")) << said.at("plot_speeds");
    EXPECT_TRUE(has(said.at("fig2_dragon_300s"), "t = 300 s")) << said.at("fig2_dragon_300s");

    // Fig. 5 names a minimum pitch that is one: collision-free just above it, colliding just
    // below (each a full run to the turning space), and its panels lie on both sides of it.
    const std::string fig5 = said.at("fig5_pitch_states");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(fig5, m, std::regex(R"(the smallest collision-free pitch is ([0-9.]+) m)"))) << fig5;
    const double least = std::stod(m[1]);
    EXPECT_FALSE(contact_before_boundary(s, least + 1e-6)) << least;
    EXPECT_TRUE(contact_before_boundary(s, least - 1e-6)) << least;
    int below = 0, above = 0;
    const std::regex panel(R"(pitch ([0-9.]+) m: )");
    for (auto p = std::sregex_iterator(fig5.begin(), fig5.end(), panel); p != std::sregex_iterator(); ++p)
        (std::stod((*p)[1]) < least ? below : above) += 1;
    EXPECT_EQ(below, 3) << fig5;
    EXPECT_EQ(above, 3) << fig5;
}

// The contest's own dragon keeps its remarks about the paper.
TEST(Figures, TheContestsScenarioKeepsThePapersRemarks) {
    const auto said = figure_texts(Scenario{}, {"plot_clearance", "plot_speeds"});
    EXPECT_TRUE(has(said.at("plot_clearance"), "First contact at t = 412.473838 s (benches 1 and 9)"));
    EXPECT_TRUE(has(said.at("plot_clearance"), "the paper's 0.1 s grid gives 413 s"));
    EXPECT_TRUE(has(said.at("plot_speeds"), "The paper's finite differences"));
}

// Three benches coil in to the centre without touching (`dragon collide` finds none): the
// figures say so instead of failing or marking a contact.
TEST(Figures, AScenarioWithoutAContactSaysSo) {
    Scenario s;
    s.bench.bench_count = 3;
    const Simulation sim(s);
    ASSERT_FALSE(first_contact(sim, 0.0, sim.valid_end()));
    const auto said = figure_texts(s, {"fig3_broad_phase", "fig4_first_contact", "plot_clearance", "fig2_dragon_300s"});
    ASSERT_EQ(said.size(), 4u);
    expect_no_paper_remark(said);
    EXPECT_TRUE(has(said.at("fig3_broad_phase"), "no two benches touch")) << said.at("fig3_broad_phase");
    EXPECT_TRUE(has(said.at("fig4_first_contact"), "No contact on the way in")) << said.at("fig4_first_contact");
    EXPECT_TRUE(has(said.at("plot_clearance"), "No contact on the way in")) << said.at("plot_clearance");
    for (const auto& [figure, text] : said) EXPECT_FALSE(has(text, "First contact")) << figure;
}

TEST(Figures, TheContestsDefaultsAreRecognised) {
    Scenario s;
    EXPECT_TRUE(is_contest_default(s));
    EXPECT_TRUE(is_contest_default(load_scenario(std::string(DRAGON_SOURCE_DIR) + "/assets/cumcm2024.toml")));
    s.path.kind = PathKind::turnaround;  // the same dragon on the other path
    EXPECT_TRUE(is_contest_default(s));
    s.bench.width = 0.25;
    EXPECT_FALSE(is_contest_default(s));
    Scenario t;
    t.head_speed = 1.5;
    EXPECT_FALSE(is_contest_default(t));
}

}  // namespace
}  // namespace dragon

namespace dragon {
namespace fs = std::filesystem;

// The gallery for papers: PDF pages poppler reads, the words on them real text.
TEST(GalleryPdf, FiguresForPapers) {
    const fs::path dir = dragon_test::scratch_dir() / "figures";
    FigureOptions fo;
    fo.asset_dir = std::string(DRAGON_SOURCE_DIR) + "/assets";  // the library reads no $DRAGON_ASSETS
    fo.theme = load_theme("light", std::string(DRAGON_SOURCE_DIR) + "/assets");
    fo.format = "pdf";
    fo.only = {"fig4_first_contact", "plot_speeds"};
    write_figures(dir.string(), Scenario{}, fo);
    for (const char* name : {"fig4_first_contact.pdf", "plot_speeds.pdf"}) {
        const auto [ok, info] = dragon_test::shell_output("pdfinfo " + (dir / name).string());
        EXPECT_TRUE(ok) << name << ": " << info;
    }
    const auto [ok, text] = dragon_test::shell_output("pdftotext " + (dir / "fig4_first_contact.pdf").string() + " -");
    ASSERT_TRUE(ok);
    EXPECT_NE(text.find("First contact at t = 412.473838 s"), std::string::npos) << text;
    EXPECT_NE(text.find("touching benches"), std::string::npos) << text;  // the legend
    fo.format = "tiff";
    EXPECT_THROW(write_figures(dir.string(), Scenario{}, fo), InputError);
}

TEST(GalleryList, EveryFigureHasItsOwnFileName) {
    std::set<std::string> names;
    for (const auto& f : dragon::figure_list()) EXPECT_TRUE(names.insert(f.name).second) << f.name;
    EXPECT_GE(names.size(), 10u);
}

}  // namespace dragon
