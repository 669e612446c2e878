// The tool's own words: the argument parser's errors said as every other refusal is (the option,
// the value, what to give; never CLI11's "Could not convert" or "At Most 1 required"), help
// without CLI11's "Excludes:" lists, counts with the noun in the singular for one, and extreme
// values in a form that can be read.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"

namespace fs = std::filesystem;
using dragon_test::contains;
using dragon_test::count_lines;
using dragon_test::run_dragon;

namespace {

// CLI11's phrases, none of which may reach the user.
const std::vector<std::string> kParserPhrases = {"Could not convert", "At Most", "At least", "required", "excludes",
                                                 "Excludes", "A subcommand", "Expected exactly"};

struct Case {
    const char* args;
    const char* says;
};

}  // namespace

TEST(CliWords, TheParsersErrorsInTheToolsWords) {
    const std::vector<Case> cases = {
        {"simulate --pitch abc", "--pitch abc is not allowed: give a number"},
        {"simulate --bench-count 2.5", "--bench-count 2.5 is not allowed: give a whole number"},
        {"simulate --pitch 0.5 --pitch 0.6", "--pitch is given 2 times: give it once"},
        {"simulate --pitch", "--pitch needs a value: give a number"},
        {"video --size", "--size needs a value: give WIDTHxHEIGHT"},
        {"film", "the storyboard is needed: give the storyboard's .toml file"},
        {"render --time 1", "--out is needed: give a file name"},
        {"figures --list --only fig1_link_geometry", "--list and --only cannot be given together"},
        {"render --time 1 --collision -o x.png", "--time and --collision cannot be given together"},
        {"min-pitch --json=3", "--json takes no value ('3' given)"},
        {"simulate --quiet=", "--quiet takes no value"},
        {"--pitch 3", "a command is needed first, then its options: simulate, solve"},
    };
    for (const Case& c : cases) {
        const dragon_test::CliRun r = run_dragon(c.args);
        EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
        EXPECT_EQ(count_lines(r.err), 1) << c.args << "\n" << r.err;
        EXPECT_TRUE(contains(r.err, c.says)) << c.args << "\n" << r.err;
        for (const std::string& phrase : kParserPhrases) EXPECT_FALSE(contains(r.err, phrase)) << c.args << "\n" << r.err;
        EXPECT_EQ(r.out, "") << c.args;
    }
}

TEST(CliWords, HelpSaysTheRulesInWordsNotExcludesLists) {
    for (const char* command : {"figures", "render", "turnaround", "simulate", "sweep", "film"}) {
        const dragon_test::CliRun r = run_dragon(std::string(command) + " --help");
        EXPECT_EQ(r.code, 0) << command;
        EXPECT_FALSE(contains(r.out, "Excludes")) << command << "\n" << r.out;
        EXPECT_FALSE(contains(r.out, "Needs:")) << command << "\n" << r.out;
    }
    EXPECT_TRUE(contains(run_dragon("figures --help").out, "takes no other option"));
    EXPECT_TRUE(contains(run_dragon("render --help").out, "not both"));
}

TEST(CliWords, OneOfAThingIsSingular) {
    const fs::path dir = dragon_test::scratch_dir();
    const dragon_test::CliRun table = run_dragon("simulate --to 0 -o " + (dir / "one.csv").string());
    EXPECT_TRUE(contains(table.err, "(1 frame x 224 handles)")) << table.err;
    const dragon_test::CliRun two = run_dragon("simulate --to 1 -o " + (dir / "two.csv").string());
    EXPECT_TRUE(contains(two.err, "(2 frames x 224 handles)")) << two.err;
    // A sweep of two rows merged from one part.
    const std::string part = (dir / "part.csv").string(), whole = (dir / "whole.csv").string();
    ASSERT_EQ(run_dragon("sweep -q --vary width=0.3,0.31 --measure collide --bench-count 20 -o " + part).code, 0);
    const dragon_test::CliRun merged = run_dragon("sweep merge " + whole + " " + part);
    EXPECT_TRUE(contains(merged.err, ": 2 rows from 1 file\n")) << merged.err;
    // A film of one title card, one frame long.
    const fs::path story = dir / "one.toml";
    std::ofstream(story) << "[film]\nsize = \"96x64\"\nfps = 5\n\n[[shot]]\ntitle = \"x\"\nduration = 0.2\n";
    const dragon_test::CliRun film = run_dragon("film " + story.string() + " -o " + (dir / "one.mp4").string());
    EXPECT_TRUE(contains(film.err, ": 1 shot, 1 frame, ")) << film.err;
}

// A limit of 1e308 m/s allows a head speed of about 6e307 m/s, and 1e-9 m/s about 6e-10 m/s:
// printed with their significant digits, as --json holds them, not as 309 digits or 0.000000.
TEST(CliWords, ExtremeValuesStayReadable) {
    const std::regex speed(R"(Largest head speed with every handle at or under \S+ m/s: (\S+) m/s)");
    for (const char* limit : {"1e308", "1e-9", "2"}) {
        const dragon_test::CliRun text = run_dragon(std::string("max-speed --limit ") + limit);
        ASSERT_EQ(text.code, 0) << text.err;
        std::smatch m;
        ASSERT_TRUE(std::regex_search(text.out, m, speed)) << text.out;
        const std::string printed = m[1];
        EXPECT_LE(printed.size(), 14u) << printed;
        const dragon_test::CliRun json = run_dragon(std::string("max-speed --json --limit ") + limit);
        const double exact = nlohmann::json::parse(json.out).at("max_head_speed").get<double>();
        EXPECT_GT(exact, 0.0);
        EXPECT_NEAR(std::stod(printed), exact, 1e-6 * exact) << limit;  // 7 significant digits at least
    }
}
