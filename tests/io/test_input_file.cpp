// Input files read without trusting them: regular files only, never past a limit, a read error
// said as one; and text the user gave shown on one line, cut when long.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "dragon/input_file.hpp"
#include "dragon/input_files.hpp"
#include "dragon/scenario.hpp"
#include "dragon/sweep.hpp"
#include "support/scratch.hpp"

namespace fs = std::filesystem;
using namespace dragon;

namespace {

std::string refusal(const std::string& path) {
    try {
        read_toml_input(path, "scenario file");
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(InputFile, ReadsARegularFileWhole) {
    const fs::path p = dragon_test::scratch_dir() / "a.toml";
    std::ofstream(p) << "width = 0.3\n";
    EXPECT_EQ(read_toml_input(p.string(), "scenario file"), "width = 0.3\n");
}

TEST(InputFile, NamesWhatIsWrongWithTheFile) {
    const fs::path dir = dragon_test::scratch_dir();
    EXPECT_EQ(refusal((dir / "none.toml").string()), "scenario file '" + (dir / "none.toml").string() + "' does not exist");
    EXPECT_TRUE(has(refusal(dir.string()), "is a folder: give a .toml file")) << refusal(dir.string());
    EXPECT_EQ(refusal("/dev/zero"), "scenario file '/dev/zero' is a device: only a regular file is read");
    // /proc/self/mem says it is a regular file of no size, and reading it fails: an error, not
    // an empty file.
    EXPECT_EQ(refusal("/proc/self/mem"), "scenario file '/proc/self/mem' cannot be read: Input/output error");
}

TEST(InputFile, AFifoIsRefusedWithoutWaitingForAWriter) {
    const fs::path fifo = dragon_test::scratch_dir() / "fifo.toml";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // With no writer, a blocking open would never return: the test would time out.
    EXPECT_EQ(refusal(fifo.string()), "scenario file '" + fifo.string() + "' is a FIFO (a named pipe): only a regular "
                                      "file is read");
}

TEST(InputFile, NoMoreThanTheLimitIsRead) {
    const fs::path p = dragon_test::scratch_dir() / "big.toml";
    {
        std::ofstream f(p);
        f << "# " << std::string(kMaxTomlBytes - 3, 'x') << "\n";  // exactly the limit
    }
    ASSERT_EQ(fs::file_size(p), kMaxTomlBytes);
    EXPECT_EQ(read_toml_input(p.string(), "scenario file").size(), kMaxTomlBytes);
    std::ofstream(p, std::ios::app) << "\n";
    EXPECT_EQ(refusal(p.string()), "scenario file '" + p.string() + "' is larger than 1 MiB, the most a scenario file "
                                   "may hold");
}

TEST(InputFile, EveryTomlReaderReadsThroughIt) {
    EXPECT_THROW(load_scenario("/dev/zero"), InputError);
    EXPECT_THROW(read_sweep_file("/dev/zero"), InputError);
    EXPECT_THROW(load_scenario("/proc/self/mem"), InputError);
    EXPECT_THROW(read_sweep_file("/proc/self/mem"), InputError);
}

TEST(ShownText, ControlCharactersEscapedAndLongTextCut) {
    EXPECT_EQ(shown_text("a\nb.csv"), "a\\nb.csv");
    EXPECT_EQ(shown_text(std::string("wid\0th", 6)), "wid\\x00th");
    EXPECT_EQ(shown_text("tab\there\r"), "tab\\there\\r");
    EXPECT_EQ(shown_text(std::string(100, 'k'), 10), "kkkkkkkkkk... (100 characters)");
    EXPECT_EQ(shown_text("short", 5), "short");
    EXPECT_EQ(shown_text(""), "");
}

}  // namespace
