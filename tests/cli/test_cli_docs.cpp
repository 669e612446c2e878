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

// The text block under each "## HEADING" of docs/cli.md, by heading. Found with std::string::find,
// not a regex: libstdc++'s regex matches `[\s\S]*?` by recursing once per character, and a block
// of a few kilobytes overflowed the stack under AddressSanitizer (its frames are larger).
std::map<std::string, std::string> blocks_by_heading() {
    const std::string doc = dragon_test::slurp(std::string(DRAGON_SOURCE_DIR) + "/docs/cli.md");
    std::map<std::string, std::string> blocks;
    const std::string heading = "\n## ", open = "```text\n", close = "```";
    for (std::size_t at = doc.find(heading); at != std::string::npos; at = doc.find(heading, at + 1)) {
        const std::size_t title_end = doc.find('\n', at + heading.size());
        if (title_end == std::string::npos) break;
        const std::string title = doc.substr(at + heading.size(), title_end - at - heading.size());
        const std::size_t next = doc.find(heading, title_end);
        const std::size_t body = doc.find(open, title_end);
        if (body == std::string::npos || (next != std::string::npos && body > next)) continue;
        const std::size_t end = doc.find(close, body + open.size());
        if (end == std::string::npos) break;
        blocks[title] = doc.substr(body + open.size(), end - body - open.size());
    }
    return blocks;
}

// Each "## `dragon ...`" heading's block, by what follows "dragon" ("", " simulate", ...).
std::map<std::string, std::string> documented() {
    std::map<std::string, std::string> commands;
    const std::string prefix = "`dragon", suffix = "`";
    for (const auto& [title, block] : blocks_by_heading())
        if (title.rfind(prefix, 0) == 0 && title.size() > prefix.size() && title.back() == '`')
            commands[title.substr(prefix.size(), title.size() - prefix.size() - suffix.size())] = block;
    return commands;
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
    const auto blocks = blocks_by_heading();
    const auto table = blocks.find("Keys");
    ASSERT_NE(table, blocks.end()) << "docs/cli.md has no key table: run bash scripts/cli-docs.sh > docs/cli.md";
    const auto r = dragon_test::run_dragon("keys");
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(table->second, r.out) << "docs/cli.md's key table is out of date: run bash scripts/cli-docs.sh > docs/cli.md";
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
