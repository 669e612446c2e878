// The docs quote the code's constants by name and value ("`tol::travel` = 1e-11 m"): every such
// quote in README.md and docs/*.md must name a constant listed here and give its value, so that a
// changed tolerance, margin or limit cannot leave the methods and the manual quoting an old one.
// Also the key reference: every key the library describes (dragon/keys.hpp) has a line in
// docs/cli.md's key table. Here rather than in tests/core: it reads the docs of every layer.
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dragon/analyses.hpp"
#include "dragon/constants.hpp"
#include "dragon/scenario.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace dragon;

namespace {

std::vector<fs::path> docs() {
    std::vector<fs::path> out{fs::path(DRAGON_SOURCE_DIR) / "README.md"};
    for (const auto& e : fs::directory_iterator(fs::path(DRAGON_SOURCE_DIR) / "docs"))
        if (e.path().extension() == ".md") out.push_back(e.path());
    return out;
}

// The constants the docs may quote, by the name they use.
const std::map<std::string, double>& quotable() {
    static const std::map<std::string, double> values = {
        {"tol::travel", tol::travel},
        {"tol::pitch", tol::pitch},
        {"tol::rate_safety", tol::rate_safety},
        {"tol::newton_step", tol::newton_step},
        {"kBroadPhaseMargin", kBroadPhaseMargin},
        {"kDefaultPitchGrid", kDefaultPitchGrid},
        {"kMaxPitchGridSteps", kMaxPitchGridSteps},
        {"kMaxBenchCount", kMaxBenchCount},
        {"kMaxReach", kMaxReach},
    };
    return values;
}

}  // namespace

TEST(DocsNumbers, EveryQuotedConstantHasItsValue) {
    const std::regex quote(R"(`((?:tol::|k)[A-Za-z_]+)` = ([-+0-9.eE]+))");
    int seen = 0;
    for (const fs::path& doc : docs()) {
        const std::string text = dragon_test::slurp(doc);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), quote); it != std::sregex_iterator(); ++it) {
            const std::string name = (*it)[1], value = (*it)[2];
            ++seen;
            const auto known = quotable().find(name);
            ASSERT_NE(known, quotable().end()) << doc.filename() << " quotes `" << name << "`, which this test does not know";
            EXPECT_EQ(std::stod(value), known->second) << doc.filename() << ": `" << name << "` = " << value;
        }
    }
    EXPECT_GE(seen, 4) << "the docs quote the tolerances by name";
}

TEST(DocsNumbers, NoStaleToleranceIsQuoted) {
    // What the docs said before tol::travel was 1e-11 m, and the margin fig3 once drew.
    for (const fs::path& doc : {fs::path("docs/library.md"), fs::path("docs/methods.md")}) {
        const std::string text = dragon_test::slurp(fs::path(DRAGON_SOURCE_DIR) / doc);
        EXPECT_EQ(text.find("to 1e-10 s"), std::string::npos) << doc;
        EXPECT_EQ(text.find("1e-10 m of head travel"), std::string::npos) << doc;
    }
}
