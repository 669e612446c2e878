// docs/cli.md is the tool's own help: each of its blocks equals what `dragon COMMAND --help`
// prints now, so the document cannot drift from the program (scripts/cli-docs.sh writes it).
#include <map>
#include <regex>
#include <set>
#include <sstream>
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

// Every flag of every command sets a key of the one description (dragon/keys.hpp) that
// `dragon keys` lists, under the key's own name: the vocabulary has no flag of the tool's alone
// but the ones that shape only how the tool answers (help, --json, --quiet, --list, --version).
TEST(CliDocs, EveryFlagIsAKeyOfTheLibrarysDescription) {
    std::set<std::string> key_flags;
    std::istringstream keys(dragon_test::run_dragon("keys").out);
    std::string line;
    std::getline(keys, line);  // the header
    while (std::getline(keys, line)) {
        std::istringstream words(line);
        std::string name, flag;
        words >> name >> flag;
        if (flag == "-") continue;
        // "--from/--to", "--[no-]legend": each flag it stands for.
        for (std::size_t start = 0; start < flag.size();) {
            const std::size_t slash = flag.find('/', start);
            std::string one = flag.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
            if (one.rfind("--[no-]", 0) == 0) {
                key_flags.insert("--" + one.substr(7));
                key_flags.insert("--no-" + one.substr(7));
            } else {
                key_flags.insert(one);
            }
            start = slash == std::string::npos ? flag.size() : slash + 1;
        }
    }
    ASSERT_TRUE(key_flags.count("--pitch") && key_flags.count("--to") && key_flags.count("--no-legend"));
    const std::set<std::string> the_tools_own = {"--help", "--json", "--quiet", "--list", "--version"};
    const std::regex option_line(R"(^\s+(?:-\w, )?(--[a-z][a-z-]*))");
    std::size_t seen = 0;
    for (const char* command : {"simulate", "solve", "collide", "min-pitch", "turnaround", "max-speed", "render",
                                "figures", "video", "film", "sweep", "sweep merge", "keys"}) {
        std::istringstream help(dragon_test::run_dragon(std::string(command) + " --help").out);
        while (std::getline(help, line)) {
            std::smatch m;
            if (!std::regex_search(line, m, option_line)) continue;
            ++seen;
            const std::string flag = m[1];
            EXPECT_TRUE(key_flags.count(flag) || the_tools_own.count(flag))
                << "dragon " << command << " " << flag << " sets no key of dragon/keys.hpp";
        }
    }
    EXPECT_GT(seen, 100u);  // the help was read
}

}  // namespace
