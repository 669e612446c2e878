// The rows' file of a sweep: rows appended whole and durable, a torn last line (a kill while it
// was written) dropped on reading and cut off on reopening, so the next row starts on its own
// line (dragon/row_files.hpp); and a sweep file read from disk.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "dragon/input_files.hpp"
#include "dragon/row_files.hpp"
#include "dragon/sweep.hpp"
#include "support/scratch.hpp"

using namespace dragon;
namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}
}  // namespace

TEST(SweepRows, TornLastLineIsDroppedAndCutOffBeforeTheNextRow) {
    const fs::path file = dragon_test::scratch_dir() / "rows.csv.partial";
    fs::remove(file);  // a log is made new: never over a file (a run before this one left one)
    {
        auto log = RowLog::create(file.string(), {"# spec", "a,b"});
        log->append("1,x");
        log->append("2,\"y, z\"");
    }
    EXPECT_EQ(slurp(file), "# spec\na,b\n1,x\n2,\"y, z\"\n");
    {
        std::ofstream torn(file, std::ios::app | std::ios::binary);
        torn << "3,par";  // what a kill in the middle of a write leaves
    }
    std::vector<std::string> preamble, rows;
    const auto scan = [&](const fs::path& p, std::size_t lines) {
        preamble.clear(), rows.clear();
        return scan_row_file(
            p.string(), lines, [&](const std::vector<std::string>& pre) { preamble = pre; },
            [&](const std::string& row) {
                EXPECT_EQ(preamble.size(), lines);  // the preamble is heard first
                rows.push_back(row);
            });
    };
    RowFileScan text = scan(file, 2);
    EXPECT_EQ(preamble, (std::vector<std::string>{"# spec", "a,b"}));
    EXPECT_EQ(text.preamble, preamble);
    EXPECT_EQ(rows, (std::vector<std::string>{"1,x", "2,\"y, z\""}));
    EXPECT_EQ(text.rows, 2u);
    EXPECT_TRUE(text.torn);
    {
        auto log = RowLog::reopen(file.string(), text.complete_bytes);
        log->append("3,again");
        log->finish((dragon_test::scratch_dir() / "rows.csv").string());
    }
    EXPECT_FALSE(fs::exists(file));
    text = scan(dragon_test::scratch_dir() / "rows.csv", 2);
    EXPECT_EQ(rows, (std::vector<std::string>{"1,x", "2,\"y, z\"", "3,again"}));
    EXPECT_FALSE(text.torn);
    EXPECT_THROW(scan(file, 2), InputError);                                   // gone
    EXPECT_THROW(scan(dragon_test::scratch_dir() / "rows.csv", 9), InputError);  // too short
    // A preamble alone (a sweep killed before its first row) is heard too.
    { auto log = RowLog::create(file.string(), {"# spec", "a,b"}); }
    text = scan(file, 2);
    EXPECT_EQ(preamble.size(), 2u);
    EXPECT_EQ(text.rows, 0u);
}

TEST(SweepFile, ReadsTheCommandLinesKeysWithTomlsNames) {
    const fs::path file = dragon_test::scratch_dir() / "map.toml";
    std::ofstream(file) << "measure = [\"min-pitch\", \"max-speed\"]\n"
                           "vary = [\"width=0.2:0.4:3\", \"body_length=1.6,2.2\"]\n"
                           "scenario = \"base.toml\"\n"
                           "[fixed]\nbench_count = 100\nspeed = 1.5\n"
                           "[min-pitch]\nlo = \"width+0.05\"\ngrid = 0.005\n";
    const SweepFile f = read_sweep_file(file.string());
    EXPECT_EQ(f.measures, (std::vector<std::string>{"min-pitch", "max-speed"}));
    // Held as --vary takes them.
    EXPECT_EQ(f.vary, (std::vector<std::string>{"width=0.2:0.4:3", "body-length=1.6,2.2"}));
    EXPECT_EQ(f.scenario, (dragon_test::scratch_dir() / "base.toml").string());  // beside the sweep file
    ASSERT_EQ(f.fixed.size(), 2u);
    EXPECT_EQ(f.fixed[0], (std::pair<std::string, std::string>{"bench_count", "100"}));
    EXPECT_EQ(f.fixed[1], (std::pair<std::string, std::string>{"speed", "1.5"}));
    ASSERT_EQ(f.options.size(), 2u);
    EXPECT_EQ(f.options[1].value, "width+0.05");
    EXPECT_TRUE(f.warnings.empty());
    for (const char* bad : {"vary = 3\n", "measure = [1]\n", "colour = \"red\"\n", "[fixed]\nwidth = true\n", "vary = [\n",
                            "[fixed]\nzoom = 2\n", "vary = [\"path=1,2\"]\n", "vary = [\"widht=1,2\"]\n"}) {
        std::ofstream(file) << bad;
        EXPECT_THROW(read_sweep_file(file.string()), InputError) << bad;
    }
}

TEST(SweepFile, TheFlagsSpellingIsAnOldNameWithOneWarningEach) {
    const SweepFile today = parse_sweep_file("vary = [\"turn_pitch=1,2\", \"arc_ratio=1:2:3\"]\n[fixed]\nbody_length = 2\n",
                                             "today.toml");
    const SweepFile old = parse_sweep_file("vary = [\"turn-pitch=1,2\", \"arc-ratio=1:2:3\"]\n[fixed]\nbody-length = 2\n",
                                           "old.toml");
    EXPECT_EQ(old.vary, today.vary);
    EXPECT_EQ(old.fixed, today.fixed);
    EXPECT_TRUE(today.warnings.empty());
    // One each, in the order of the file's keys ([fixed] before vary).
    ASSERT_EQ(old.warnings.size(), 3u);
    EXPECT_EQ(old.warnings[0].key, Key::body_length);
    EXPECT_EQ(old.warnings[0].message, "sweep file 'old.toml': [fixed] body-length is an old name: write body_length = 2");
    EXPECT_EQ(old.warnings[1].key, Key::turn_pitch);
    EXPECT_EQ(old.warnings[1].old_name, "turn-pitch");
    EXPECT_EQ(old.warnings[1].message,
              "sweep file 'old.toml': vary \"turn-pitch=1,2\" is an old name: write \"turn_pitch=1,2\"");
    EXPECT_EQ(old.warnings[2].key, Key::arc_ratio);
    // Parsing reads no file; the scenario it names is beside it, joined as text.
    EXPECT_EQ(parse_sweep_file("scenario = \"base.toml\"\n", "a/b.toml").scenario, "a/base.toml");
}

TEST(SweepRows, LinesPastTheirLimitAndForeignLineEndsAreRefusedAsRead) {
    const fs::path file = dragon_test::scratch_dir() / "limits.csv";
    const auto scan = [&](const std::string& text, const RowFileLimits& limits) -> std::string {
        std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
        try {
            scan_row_file(file.string(), 2, [](const std::vector<std::string>&) {}, [](const std::string&) {}, limits);
        } catch (const InputError& e) {
            return e.what();
        }
        return "accepted";
    };
    RowFileLimits limits;
    limits.preamble_line_bytes = 20;
    limits.row_bytes = 10;
    const std::string named = "sweep rows '" + file.string() + "'";
    EXPECT_EQ(scan("# spec\na,b\n1234567890\n", limits), "accepted");
    EXPECT_EQ(scan("# spec\na,b\n12345678901\n", limits),
              named + ": line 3 is longer than 10 bytes, the most a row of it may hold");
    // A row too long is refused even when it is the torn last one.
    EXPECT_EQ(scan("# spec\na,b\n12345678901", limits), named + ": line 3 is longer than 10 bytes, the most a row of it may hold");
    EXPECT_EQ(scan("# " + std::string(19, 's') + "\n", limits),
              named + ": line 1 is longer than 20 bytes, the most a first line of it may hold");
    EXPECT_EQ(scan("# spec\r\na,b\n", limits),
              named + ": line 1 ends in CR LF, and a sweep's lines end in LF alone (was it edited elsewhere?)");
    limits.what = "sweep part";
    EXPECT_EQ(scan("# spec\n", limits), "sweep part '" + file.string() + "' is not a sweep's rows: it has 1 complete "
                                        "line, and a sweep's file starts with 2");
    // Only a regular file is read.
    try {
        scan_row_file("/dev/zero", 2, [](const std::vector<std::string>&) {}, [](const std::string&) {});
        ADD_FAILURE() << "/dev/zero read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "sweep rows '/dev/zero' is a device: only a regular file is read");
    }
    EXPECT_THROW(read_first_line("/dev/zero"), InputError);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << "# spec\na,b\n";
    EXPECT_EQ(read_first_line(file.string()), "# spec");
    std::ofstream(file, std::ios::binary | std::ios::trunc) << "# no line end";
    EXPECT_THROW(read_first_line(file.string()), InputError);
}
