// The library speaks in its own terms: no string in its sources names a command-line flag
// ("--fps"). Its errors name values ("frame rate") and the CLI words them with its flags
// (src/cli/error_words.cpp). Here rather than in tests/core: it reads the sources of every layer.
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace fs = std::filesystem;

namespace {

struct Literal {
    int line;
    std::string text;  // as written, escapes and all
};

// The string literals of a C++ source, comments left out: // to the end of a line and /* */.
// Character literals ('"') and digit separators (1'000) are skipped; raw strings R"x(...)x" are
// read to their closing delimiter. Enough for this code base, which has no macros that paste
// strings and no trigraphs.
std::vector<Literal> string_literals(const std::string& source) {
    std::vector<Literal> out;
    int line = 1;
    const std::size_t n = source.size();
    const auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (std::size_t i = 0; i < n; ++i) {
        const char c = source[i];
        if (c == '\n') {
            ++line;
        } else if (c == '/' && i + 1 < n && source[i + 1] == '/') {
            while (i < n && source[i] != '\n') ++i;
            --i;  // the newline is counted above
        } else if (c == '/' && i + 1 < n && source[i + 1] == '*') {
            for (i += 2; i + 1 < n && !(source[i] == '*' && source[i + 1] == '/'); ++i) line += source[i] == '\n';
            ++i;
        } else if (c == '\'' && i > 0 && std::isxdigit(static_cast<unsigned char>(source[i - 1]))) {
            // 1'000'000: a digit separator (a char literal never follows a digit).
        } else if (c == '\'') {
            for (++i; i < n && source[i] != '\''; ++i)
                if (source[i] == '\\') ++i;
        } else if (c == 'R' && i + 1 < n && source[i + 1] == '"' && (i == 0 || !ident(source[i - 1]) ||
                                                                     source[i - 1] == '8' || source[i - 1] == 'u' ||
                                                                     source[i - 1] == 'U' || source[i - 1] == 'L')) {
            const std::size_t open = source.find('(', i + 2);
            std::string close(1, ')');  // )delimiter"
            close.append(source, i + 2, open - (i + 2)).push_back('"');
            const std::size_t end = source.find(close, open);
            Literal lit{line, source.substr(open + 1, end - open - 1)};
            for (std::size_t k = i; k < end; ++k) line += source[k] == '\n';
            out.push_back(lit);
            i = end + close.size() - 1;
        } else if (c == '"') {
            Literal lit{line, ""};
            for (++i; i < n && source[i] != '"'; ++i) {
                if (source[i] == '\\' && i + 1 < n) lit.text += source[i++];
                lit.text += source[i];
            }
            out.push_back(lit);
        }
    }
    return out;
}

// "--" then a lowercase letter: a long flag, as the CLI spells them.
bool names_a_flag(const std::string& text) {
    for (std::size_t i = 0; i + 2 < text.size(); ++i)
        if (text[i] == '-' && text[i + 1] == '-' && std::islower(static_cast<unsigned char>(text[i + 2]))) return true;
    return false;
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

TEST(LibraryWords, TheScannerFindsLiteralsAndSkipsComments) {
    const auto texts = [](const std::string& src) {
        std::vector<std::string> t;
        for (const Literal& l : string_literals(src)) t.push_back(l.text);
        return t;
    };
    using V = std::vector<std::string>;
    EXPECT_EQ(texts("f(\"--fps\");  // \"--to\" in a comment\n"), V{"--fps"});
    EXPECT_EQ(texts("// throw \"--fps\"\n   // \"--to\"\nx = 1;"), V{});
    EXPECT_EQ(texts("/* \"--fps\"\n \"--to\" */ g(\"a\");"), V{"a"});
    EXPECT_EQ(texts("c = '\"'; s = \"--x\";"), V{"--x"});
    EXPECT_EQ(texts("c = '\\''; n = 1'000'000; s = \"b\";"), V{"b"});
    EXPECT_EQ(texts("s = \"a \\\" // not a comment --y\";"), V{"a \\\" // not a comment --y"});
    EXPECT_EQ(texts("s = R\"x(--z \" )\" )x\"; t = \"w\";"), (V{"--z \" )\" ", "w"}));
    EXPECT_EQ(texts("url = \"http://a\"; // \"--c\""), V{"http://a"});
    // Lines are counted through comments and raw strings.
    const auto lits = string_literals("/*\n\n*/\nR\"(\n)\"\n\"here\"");
    ASSERT_EQ(lits.size(), 2u);
    EXPECT_EQ(lits[1].line, 6);

    EXPECT_TRUE(names_a_flag("raise --speedup or lower"));
    EXPECT_FALSE(names_a_flag("a -- b"));
    EXPECT_FALSE(names_a_flag("--X"));
    EXPECT_FALSE(names_a_flag("i--"));
}

TEST(LibraryWords, NoLibrarySourceNamesAFlag) {
    const fs::path root(DRAGON_SOURCE_DIR);
    int files = 0;
    // The layers' sources and their public headers.
    for (const char* layer : {"src/core", "src/answers", "src/render", "src/video", "src/film", "src/tables", "include/dragon"}) {
        ASSERT_TRUE(fs::is_directory(root / layer)) << (root / layer);
        for (const auto& entry : fs::recursive_directory_iterator(root / layer)) {
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
            ++files;
            for (const Literal& lit : string_literals(slurp(entry.path())))
                EXPECT_FALSE(names_a_flag(lit.text))
                    << fs::relative(entry.path(), DRAGON_SOURCE_DIR).string() << ":" << lit.line << ": \"" << lit.text
                    << "\" names a command-line flag: name the value in the library's terms (InputError's field) "
                       "and word it with the flag in src/cli/error_words.cpp";
        }
    }
    EXPECT_GT(files, 50);  // the sources were found
}

}  // namespace
