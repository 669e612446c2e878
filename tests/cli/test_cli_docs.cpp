// docs/cli.md is the tool's own help: each of its blocks equals what `dragon COMMAND --help`
// prints now, so the document cannot drift from the program (scripts/cli-docs.sh writes it).
#include <map>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_run.hpp"

namespace {

// Each "## `dragon ...`" heading of docs/cli.md and the text block under it.
std::map<std::string, std::string> documented() {
    const std::string doc = dragon_test::slurp(std::string(DRAGON_SOURCE_DIR) + "/docs/cli.md");
    std::map<std::string, std::string> blocks;
    const std::regex block("## `dragon([^`]*)`\\n\\n```text\\n([\\s\\S]*?)```");
    for (auto it = std::sregex_iterator(doc.begin(), doc.end(), block); it != std::sregex_iterator(); ++it)
        blocks[(*it)[1]] = (*it)[2];
    return blocks;
}

TEST(CliDocs, EveryCommandsHelpIsDocumentedAsTheToolPrintsIt) {
    const auto blocks = documented();
    for (const char* command : {"", " simulate", " solve", " collide", " min-pitch", " turnaround", " max-speed", " render",
                                " figures", " video", " film", " sweep", " sweep merge"}) {
        const auto it = blocks.find(command);
        ASSERT_NE(it, blocks.end()) << "docs/cli.md has no section for 'dragon" << command << "'";
        const auto r = dragon_test::run_dragon(std::string(command) + " --help");
        EXPECT_EQ(r.code, 0) << command;
        EXPECT_EQ(it->second, r.out) << "docs/cli.md is out of date for 'dragon" << command
                                     << "': run bash scripts/cli-docs.sh > docs/cli.md";
    }
}

TEST(CliDocs, TheKeyReferenceIsTheLibrarysDescription) {
    // docs/cli.md's key table is `dragon keys` as it prints now, and that lists every key of
    // dragon/keys.hpp by the names the flags, TOML files and Python use.
    const std::string doc = dragon_test::slurp(std::string(DRAGON_SOURCE_DIR) + "/docs/cli.md");
    const std::smatch m = [&] {
        std::smatch found;
        std::regex_search(doc, found, std::regex("## Keys\\n[\\s\\S]*?```text\\n([\\s\\S]*?)```"));
        return found;
    }();
    ASSERT_FALSE(m.empty()) << "docs/cli.md has no key table: run bash scripts/cli-docs.sh > docs/cli.md";
    const auto r = dragon_test::run_dragon("keys");
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(m[1].str(), r.out) << "docs/cli.md's key table is out of date: run bash scripts/cli-docs.sh > docs/cli.md";
    for (const char* flag : {"--pitch", "--speed", "--bench-count", "--hole-offset", "--arc-ratio", "--from", "--grid"})
        EXPECT_NE(r.out.find(flag), std::string::npos) << flag;
}

}  // namespace
