// The paper's tables (`dragon solve --tables`, `simulate --table`): their numbers are the
// library's handles at the moments the contest names, computed here on their own and rounded
// as the workbooks round them; the LaTeX compiles with xelatex where a TeX is installed.
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dragon/analyses.hpp"
#include "dragon/chain.hpp"
#include "dragon/scenario.hpp"
#include "dragon/tables.hpp"
#include "support/cli_run.hpp"
#include "support/scratch.hpp"

namespace {

using dragon_test::run_dragon;
using dragon_test::slurp;
namespace fs = std::filesystem;

std::vector<std::vector<std::string>> read_csv(const fs::path& p) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(slurp(p));
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream l(line);
        while (std::getline(l, cell, ',')) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.push_back("");
        rows.push_back(cells);
    }
    return rows;
}

const int kHandles[] = {0, 1, 51, 101, 151, 201, 223};

std::string six(double v) { return dragon::format_fixed(v, 6); }

// A positions table: x and y rows of each paper handle, a column per moment.
void expect_positions(const std::vector<std::vector<std::string>>& t, const dragon::Simulation& sim,
                      const std::vector<double>& times) {
    ASSERT_EQ(t.size(), 1 + 2 * std::size(kHandles));
    for (std::size_t k = 0; k < times.size(); ++k) {
        EXPECT_EQ(t[0][k + 1], fmt::format("{} s", dragon::format_time(times[k], 6)));
        const dragon::Frame f = sim.frame(times[k]);
        for (std::size_t i = 0; i < std::size(kHandles); ++i) {
            const auto& h = f.handles[static_cast<std::size_t>(kHandles[i])];
            EXPECT_EQ(t[1 + 2 * i][k + 1], six(h.pos.x())) << t[1 + 2 * i][0] << " at " << times[k];
            EXPECT_EQ(t[2 + 2 * i][k + 1], six(h.pos.y())) << t[2 + 2 * i][0] << " at " << times[k];
        }
    }
}

void expect_speeds(const std::vector<std::vector<std::string>>& t, const dragon::Simulation& sim,
                   const std::vector<double>& times) {
    ASSERT_EQ(t.size(), 1 + std::size(kHandles));
    for (std::size_t k = 0; k < times.size(); ++k) {
        const dragon::Frame f = sim.frame(times[k]);
        for (std::size_t i = 0; i < std::size(kHandles); ++i)
            EXPECT_EQ(t[1 + i][k + 1], six(f.handles[static_cast<std::size_t>(kHandles[i])].speed)) << t[1 + i][0];
    }
}

// Each test solves into its own scratch folder (ctest runs the tests in parallel, a process each).
class SolveTables : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = dragon_test::fresh_dir("solved");
        for (const char* f : {"csv", "latex", "markdown"}) {
            const auto r = run_dragon(fmt::format("solve --only q1,q2,q4 --tables {} -q -o {}/{}", f, dir_.string(), f));
            ASSERT_EQ(r.code, 0) << r.err;
        }
        const auto zh = run_dragon(fmt::format("solve --only q1,q2,q4 --tables latex --lang zh -q -o {}/zh", dir_.string()));
        ASSERT_EQ(zh.code, 0) << zh.err;
    }
    fs::path dir_;
};

TEST_F(SolveTables, Q1AndQ4TablesHoldTheHandlesAtTheContestsMoments) {
    dragon::Scenario s;
    const dragon::Simulation spiral(s);
    expect_positions(read_csv(dir_ / "csv/table_q1_positions.csv"), spiral, {0, 60, 120, 180, 240, 300});
    expect_speeds(read_csv(dir_ / "csv/table_q1_speeds.csv"), spiral, {0, 60, 120, 180, 240, 300});
    // The published values (PROBLEM.md): handle 1 at t = 0.
    EXPECT_EQ(read_csv(dir_ / "csv/table_q1_positions.csv")[3][1], "8.363824");
    s.path.kind = dragon::PathKind::turnaround;
    const dragon::Simulation turn(s);
    expect_positions(read_csv(dir_ / "csv/table_q4_positions.csv"), turn, {-100, -50, 0, 50, 100});
    expect_speeds(read_csv(dir_ / "csv/table_q4_speeds.csv"), turn, {-100, -50, 0, 50, 100});
}

TEST_F(SolveTables, Q2TableAndTheAnswersHoldTheFirstContact) {
    const dragon::Simulation sim{dragon::Scenario{}};
    const dragon::CollideAnswer a = dragon::collide(sim, {dragon::Along::metres(0), dragon::Along::metres(430)});
    ASSERT_TRUE(a.contact);
    const auto t = read_csv(dir_ / "csv/table_q2_contact.csv");
    ASSERT_EQ(t.size(), 1 + std::size(kHandles));
    for (std::size_t i = 0; i < std::size(kHandles); ++i) {
        const auto& h = a.contact->frame.handles[static_cast<std::size_t>(kHandles[i])];
        EXPECT_EQ(t[1 + i][1], six(h.pos.x()));
        EXPECT_EQ(t[1 + i][2], six(h.pos.y()));
        EXPECT_EQ(t[1 + i][3], six(h.speed));
    }
    const std::string answers = slurp(dir_ / "csv/table_answers.csv");
    EXPECT_NE(answers.find("412.47383768"), std::string::npos) << answers;
    EXPECT_NE(answers.find("13.621245"), std::string::npos) << answers;
}

// Every number of the LaTeX and Markdown tables is the CSV's, in the same order.
// (The captions' numbers are not the table's.)
std::vector<std::string> numbers_in(const std::string& text) {
    static const std::regex number(R"((^|[ |&])(-?\d+\.\d+)(?=[ |\\]))");
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.find("\\caption") != std::string::npos || line.starts_with("Table: ")) continue;
        for (auto it = std::sregex_iterator(line.begin(), line.end(), number); it != std::sregex_iterator(); ++it)
            out.push_back((*it)[2]);
    }
    return out;
}
std::vector<std::string> numbers_in_csv(const fs::path& p) {
    std::vector<std::string> out;
    for (const auto& row : read_csv(p))
        for (std::size_t c = 1; c < row.size(); ++c)
            if (std::regex_match(row[c], std::regex(R"(-?\d+\.\d+)"))) out.push_back(row[c]);
    return out;
}

TEST_F(SolveTables, LatexAndMarkdownHoldTheCsvsNumbersWithRulesCaptionsAndLabels) {
    for (const char* id : {"q1_positions", "q1_speeds", "q2_contact", "q4_positions", "q4_speeds", "answers"}) {
        const std::vector<std::string> csv = numbers_in_csv(dir_ / fmt::format("csv/table_{}.csv", id));
        ASSERT_FALSE(csv.empty()) << id;
        const std::string tex = slurp(dir_ / fmt::format("latex/table_{}.tex", id));
        EXPECT_EQ(numbers_in(tex), csv) << id;
        for (const char* part : {"\\toprule", "\\midrule", "\\bottomrule", "\\caption{", "S[table-format="})
            EXPECT_NE(tex.find(part), std::string::npos) << id << " lacks " << part;
        EXPECT_NE(tex.find(fmt::format("\\label{{tab:dragon-{}}}", std::regex_replace(id, std::regex("_"), "-"))),
                  std::string::npos) << tex;
        const std::string md = slurp(dir_ / fmt::format("markdown/table_{}.md", id));
        EXPECT_EQ(numbers_in(md), csv) << id;
        EXPECT_NE(md.find("\nTable: "), std::string::npos) << md;
        EXPECT_NE(md.find("---:|"), std::string::npos) << md;  // numbers right-aligned
    }
    const std::string zh = slurp(dir_ / "zh/table_q1_positions.tex");
    EXPECT_NE(zh.find("第101节龙身x (m)"), std::string::npos) << zh;
    EXPECT_NE(zh.find("龙尾（后）y (m)"), std::string::npos) << zh;
    EXPECT_EQ(numbers_in(zh), numbers_in_csv(dir_ / "csv/table_q1_positions.csv"));
}

// xelatex with ctex (Chinese) and booktabs and siunitx: every table, in English and in Chinese,
// on an A4 page with 2.5 cm margins (CUMCM's template; 16 cm of text, the tool's --print a4),
// none wider than the text.
TEST_F(SolveTables, LatexCompilesWithXelatex) {
    if (std::system("command -v xelatex >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "xelatex is not installed (Debian: texlive-xetex texlive-latex-recommended texlive-science "
                        "texlive-lang-chinese)";
    if (std::system("kpsewhich ctexart.cls >/dev/null 2>&1") != 0 || std::system("kpsewhich siunitx.sty >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "ctex or siunitx is not installed (Debian: texlive-lang-chinese, texlive-science)";
    for (const char* lang : {"latex", "zh"}) {
        const fs::path d = dir_ / lang;
        std::string doc = "\\documentclass[a4paper]{ctexart}\n\\usepackage[margin=2.5cm]{geometry}\n"
                          "\\usepackage{booktabs,siunitx}\n\\begin{document}\n";
        for (const char* id : {"q1_positions", "q1_speeds", "q2_contact", "q4_positions", "q4_speeds", "answers"})
            doc += fmt::format("\\input{{table_{}.tex}}\n", id);
        doc += "\\end{document}\n";
        std::FILE* f = std::fopen((d / "paper.tex").c_str(), "w");
        ASSERT_TRUE(f);
        std::fputs(doc.c_str(), f);
        std::fclose(f);
        const auto [ok, log] = dragon_test::shell_output(
            fmt::format("cd {} && xelatex -interaction=nonstopmode -halt-on-error paper.tex 2>&1", d.string()));
        EXPECT_TRUE(ok && fs::exists(d / "paper.pdf")) << log.substr(log.size() > 3000 ? log.size() - 3000 : 0);
        EXPECT_EQ(log.find("Overfull \\hbox"), std::string::npos) << lang << ": a table is wider than the text";
    }
}

TEST(SimulateTable, PrintsThePaperHandlesAtEachStep) {
    const auto r = run_dragon("simulate --to 300 --step 100 --table markdown");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("|  | 0 s | 100 s | 200 s | 300 s |"), std::string::npos) << r.out;
    const dragon::Frame f = dragon::Simulation(dragon::Scenario{}).frame(200);
    EXPECT_NE(r.out.find(six(f.handles[101].pos.x())), std::string::npos);
    EXPECT_NE(r.out.find(six(f.handles[223].speed)), std::string::npos);
    const auto csv = run_dragon("simulate --to 2 --table csv --lang zh");
    ASSERT_EQ(csv.code, 0) << csv.err;
    EXPECT_EQ(csv.out.substr(0, csv.out.find('\n')), ",0 s,1 s,2 s");
    EXPECT_NE(csv.out.find("龙头 (m/s),1.000000,1.000000,1.000000"), std::string::npos) << csv.out;
    // Too many columns for a table; a file that is not the format's.
    EXPECT_EQ(run_dragon("simulate --to 300 --table latex").code, 2);
    EXPECT_EQ(run_dragon("simulate --to 2 --table latex -o t.md").code, 2);
    EXPECT_EQ(run_dragon("simulate --to 2 --table word").code, 2);
}

TEST(FiguresData, NamesEveryFileItWrote) {
    const fs::path dir = dragon_test::fresh_dir("figs");
    const auto r = run_dragon(fmt::format("figures --only plot_clearance,fig4_first_contact --data -o {}", dir.string()));
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* f : {"plot_clearance.png", "plot_clearance.csv", "fig4_first_contact.png", "fig4_first_contact.csv"}) {
        EXPECT_TRUE(fs::exists(dir / f)) << f;
        EXPECT_NE(r.err.find((dir / f).string()), std::string::npos) << f << " not named in:\n" << r.err;
    }
}

}  // namespace
