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

}  // namespace
