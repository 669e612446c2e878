// A sweep's rows files as the library writes, resumes and merges them (dragon/sweep_files.hpp):
// a file left by a kill (a torn last line) and holding a failed row is finished to exactly the
// bytes of a sweep never stopped; merging refuses a part missing, a part twice and a part of
// another sweep, leaving no file; and the output's refusals name their key.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dragon/sweep_files.hpp"
#include "support/scratch.hpp"

using namespace dragon;
namespace fs = std::filesystem;

namespace {

// Three quick scenarios (max-speed on short chains, a few milliseconds each), or one part of them.
SweepSetup small_sweep(const std::string& shard = "", double limit = 2.0) {
    SweepAsked asked;
    asked.vary = {"bench-count=20:40:3"};
    asked.measures = {"max-speed"};
    asked.limit = limit;
    asked.shard = shard;
    const SweepWords words{[](const char* option) { return std::string(option); },
                           [](const char* value) { return std::string(value); }};
    return make_sweep_setup(asked, words, [](ScenarioValues, const std::string&) { return Scenario{}; });
}

// The file's lines, without their line ends.
std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = text.find('\n', at);
        out.push_back(text.substr(at, end - at));
        at = end == std::string::npos ? text.size() : end + 1;
    }
    return out;
}

// The sweep written in one go, on the calling thread (so its rows are in the grid's order).
std::string written_whole(const SweepSetup& setup, const fs::path& out) {
    InlineExecutor inline_ex;
    const SweepTally t = write_sweep(setup, {out.string(), false}, inline_ex);
    EXPECT_EQ(t.made, setup.shard.size(setup.grid.size()));
    EXPECT_EQ(t.failed, 0u);
    return dragon_test::slurp(out);
}

// The InputError `f` throws (its key and value), or a failure.
template <class F>
InputError refusal(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no InputError";
    return InputError("none");
}

}  // namespace

TEST(SweepFiles, ResumingATornLastLineAndAFailedRowFinishesTheSweepsBytes) {
    const fs::path dir = dragon_test::fresh_dir("resume");
    const SweepSetup setup = small_sweep();
    const std::string whole = written_whole(setup, dir / "whole.csv");
    const std::vector<std::string> lines = lines_of(whole);
    ASSERT_EQ(lines.size(), 5u);  // the spec line, the header, three rows

    // What a kill leaves after a run whose second row failed: the first row, the second as a
    // failed measure writes it (its cells empty, its status saying so), the third cut short.
    const std::size_t columns = header(setup).size();
    std::string failed = split_csv(lines[3])[0];
    for (std::size_t k = 1; k + 1 < columns; ++k) failed += ",";
    failed += ",failed (max-speed): the search did not converge";
    const fs::path out = dir / "rows.csv";
    std::ofstream(partial_path(out.string()), std::ios::binary)
        << lines[0] << "\n" << lines[1] << "\n" << lines[2] << "\n" << failed << "\n" << lines[4].substr(0, 7);

    std::vector<std::string> notes;
    std::vector<std::size_t> heard;
    SweepCallbacks cb;
    cb.on_row = [&](std::size_t scenario, const std::string&) { heard.push_back(scenario); };
    cb.on_note = [&](const std::string& note) { notes.push_back(note); };
    InlineExecutor inline_ex;
    const SweepTally t = write_sweep(setup, {out.string(), true}, inline_ex, cb);
    EXPECT_EQ(t.done_before, 1u);
    EXPECT_EQ(t.made, 2u);
    EXPECT_EQ(t.failed, 0u);
    EXPECT_EQ(heard, (std::vector<std::size_t>{0, 1, 2}));  // the resumed row first
    ASSERT_EQ(notes.size(), 2u);
    EXPECT_NE(notes[0].find("1 failed row"), std::string::npos) << notes[0];
    EXPECT_NE(notes[1].find("1 of 3 rows"), std::string::npos) << notes[1];
    EXPECT_EQ(dragon_test::slurp(out), whole);
    EXPECT_FALSE(fs::exists(partial_path(out.string())));

    // A finished sweep resumed makes nothing and keeps its bytes.
    const SweepTally again = write_sweep(setup, {out.string(), true}, inline_ex);
    EXPECT_EQ(again.done_before, 3u);
    EXPECT_EQ(again.made, 0u);
    EXPECT_EQ(dragon_test::slurp(out), whole);
}

TEST(SweepFiles, TheWriterTakesRowsFromElsewhereAndSaysWhatIsDone) {
    // What a front end with its own workers does: asks which rows are done, makes the others
    // where it likes, and appends them.
    const fs::path dir = dragon_test::fresh_dir("writer");
    const SweepSetup setup = small_sweep();
    const std::string whole = written_whole(setup, dir / "whole.csv");
    const std::vector<std::string> lines = lines_of(whole);
    const fs::path out = dir / "rows.csv";
    std::ofstream(partial_path(out.string()), std::ios::binary) << lines[0] << "\n" << lines[1] << "\n" << lines[2] << "\n";
    SweepWriter writer(setup, {out.string(), true});
    EXPECT_EQ(writer.done(), (std::vector<bool>{true, false, false}));
    EXPECT_EQ(writer.done_before(), 1u);
    EXPECT_EQ(writer.resumed_from(), partial_path(out.string()));
    writer.append(make_row(setup, 1).csv);
    writer.append(make_row(setup, 2).csv);
    writer.finish();
    EXPECT_EQ(dragon_test::slurp(out), whole);
}

TEST(SweepFiles, ResumingAnotherSweepsRowsIsRefused) {
    const fs::path dir = dragon_test::fresh_dir("another");
    written_whole(small_sweep("", 1.9), dir / "other.csv");
    fs::rename(dir / "other.csv", partial_path((dir / "rows.csv").string()));
    const InputError e = refusal([&] { SweepWriter(small_sweep(), {(dir / "rows.csv").string(), true}); });
    EXPECT_EQ(e.key(), Key::resume);
    EXPECT_EQ(e.value(), "true");
    EXPECT_NE(e.allowed().find("another sweep"), std::string::npos) << e.what();
}

TEST(SweepFiles, TheOutputsRefusalsNameTheirKey) {
    const fs::path dir = dragon_test::fresh_dir("output");
    InputError e = refusal([] { check_sweep_output({"", true}); });
    EXPECT_EQ(e.key(), Key::resume);
    EXPECT_EQ(e.value(), "true");
    e = refusal([&] { check_sweep_output({(dir / "rows.txt").string(), false}); });
    EXPECT_EQ(e.key(), Key::out);
    EXPECT_EQ(e.value(), (dir / "rows.txt").string());
    // An unfinished sweep's rows are not started afresh over: resuming is what is missing.
    std::ofstream(partial_path((dir / "rows.csv").string())) << "rows\n";
    e = refusal([&] { check_sweep_output({(dir / "rows.csv").string(), false}); });
    EXPECT_EQ(e.key(), Key::resume);
    EXPECT_EQ(e.value(), "false");
    EXPECT_NE(e.allowed().find(partial_path((dir / "rows.csv").string())), std::string::npos) << e.what();
    fs::remove(partial_path((dir / "rows.csv").string()));
    fs::create_symlink(dir / "elsewhere.csv", partial_path((dir / "rows.csv").string()));
    e = refusal([&] { check_sweep_output({(dir / "rows.csv").string(), true}); });
    EXPECT_EQ(e.key(), Key::out);
}

TEST(SweepFiles, MergedPartsHoldEveryScenarioOnceAndNothingElse) {
    const fs::path dir = dragon_test::fresh_dir("merge");
    const std::string whole = written_whole(small_sweep(), dir / "whole.csv");
    const std::string part1 = (dir / "part1.csv").string(), part2 = (dir / "part2.csv").string();
    written_whole(small_sweep("1/2"), part1);
    written_whole(small_sweep("2/2"), part2);
    const std::string merged = (dir / "merged.csv").string();

    const SweepSetup setup = whole_sweep({part1, part2});
    EXPECT_EQ(spec_line(setup), lines_of(whole)[0]);
    std::vector<std::size_t> heard;
    const std::size_t rows =
        merge_sweep_parts(setup, merged, {part1, part2}, [&](std::size_t s, const std::string&) { heard.push_back(s); });
    EXPECT_EQ(rows, 3u);
    EXPECT_EQ(heard, (std::vector<std::size_t>{0, 2, 1}));  // the parts' rows, in the files' order
    const std::vector<std::string> w = lines_of(whole);
    EXPECT_EQ(dragon_test::slurp(merged), w[0] + "\n" + w[1] + "\n" + w[2] + "\n" + w[4] + "\n" + w[3] + "\n");
    fs::remove(merged);

    // Each refusal leaves no merged file.
    const auto refused = [&](const std::vector<std::string>& parts, const std::string& words) {
        const InputError e = refusal([&] { merge_sweep_parts(setup, merged, parts); });
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        EXPECT_FALSE(fs::exists(merged));
    };
    refused({part1}, "1 of the sweep's 3 scenarios is missing, the first: bench-count=30");
    refused({part1, part2, part1}, "twice");
    written_whole(small_sweep("2/2", 1.9), (dir / "other.csv").string());
    refused({part1, (dir / "other.csv").string()}, "is not a part of the sweep");
    std::ofstream((dir / "torn.csv").string(), std::ios::binary) << dragon_test::slurp(part2) << "30,";
    refused({part1, (dir / "torn.csv").string()}, "torn");
    const InputError e = refusal([&] { merge_sweep_parts(setup, (dir / "merged.txt").string(), {part1, part2}); });
    EXPECT_EQ(e.key(), Key::out);
}
