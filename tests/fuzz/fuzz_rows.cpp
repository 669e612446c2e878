// libFuzzer target: a sweep's rows read back (--resume's partial file, sweep merge's parts).
//
// Input: the bytes of a rows' file. When the first byte is 'P' the rest follows the real first
// two lines of a small sweep (what it is, its header), so that the fuzzer reaches the rows
// without having to guess a 600-byte first line; otherwise the whole input is the file.
//
// Properties:
//  - reading returns or throws InputError: nothing else escapes (std::out_of_range, a JSON
//    parse error, bad_alloc from a line read whole), and no line handed on is longer than its
//    limit;
//  - a row check_row takes is a row this sweep could have written: one cell per column, no
//    control character, its varied values a scenario of the sweep, every measure either
//    answered (its JSON-looking cells reading as JSON) or noted as refused or failed.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/scenario_flags.hpp"
#include "dragon/sweep_row_check.hpp"
#include "cli/sweep_setup.hpp"
#include "dragon/row_files.hpp"
#include "dragon/sweep.hpp"
#include "fuzz_check.hpp"

namespace {

using namespace dragon;
using namespace dragon::cli;

const SweepSetup& setup() {
    static const SweepSetup s = [] {
        CLI::App app{"fuzz"};
        ScenarioFlags flags;
        Registry reg;
        flags.add_to(app.add_subcommand("sweep", ""), ScenarioUse::both_paths(""), reg);
        SweepRequest req;
        req.vary = {"arc-ratio=1,1.5,2", "turn-pitch=1.5,1.7"};
        req.measures = {"turnaround", "max-speed"};
        return make_setup(req, flags, nullptr);  // no run: the fuzzer reads rows, writes no outputs
    }();
    return s;
}

const std::string& rows_path() {
    static const std::string path = "/tmp/dragon-fuzz-rows-" + std::to_string(::getpid()) + ".csv";
    return path;
}

void write_file(const std::string& path, const std::string& text) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    FUZZ_CHECK(f != nullptr, "cannot write %s", path.c_str());
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
}

void check_taken(const std::string& row, std::size_t index) {
    const SweepSetup& s = setup();
    FUZZ_CHECK(index < s.grid.size(), "scenario %zu of %zu", index, s.grid.size());
    for (const char c : row) FUZZ_CHECK(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, "control character taken");
    const std::vector<std::string> cells = split_csv(row);
    FUZZ_CHECK(cells.size() == header(s).size(), "%zu cells taken", cells.size());
    const std::vector<std::string> axes = s.grid.cells(index);
    for (std::size_t k = 0; k < axes.size(); ++k) FUZZ_CHECK(cells[k] == axes[k], "axis cell %zu", k);
    FUZZ_CHECK(!cells.back().empty(), "an empty status taken");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    const std::string preamble = spec_line(setup()) + "\n" + csv_line(header(setup())) + "\n";
    const std::string file = !input.empty() && input[0] == 'P' ? preamble + input.substr(1) : input;
    write_file(rows_path(), file);
    const RowFileLimits limits = row_limits(setup(), "sweep rows");
    fuzz_context() = "a rows' file of " + std::to_string(file.size()) + " bytes";
    try {
        try {
            scan_row_file(
                rows_path(), 2,
                [&](const std::vector<std::string>& found) {
                    FUZZ_CHECK(found.size() == 2, "a preamble of %zu lines", found.size());
                    for (const std::string& line : found)
                        FUZZ_CHECK(line.size() <= limits.preamble_line_bytes, "a first line of %zu bytes", line.size());
                    if (found[0] + "\n" + found[1] + "\n" != preamble)
                        throw InputError(spec_difference(found[0], spec_line(setup())));
                },
                [&](const std::string& row) {
                    FUZZ_CHECK(row.size() <= limits.row_bytes, "a row of %zu bytes", row.size());
                    const RowCheck check = check_row(setup(), row);
                    FUZZ_CHECK(check.index.has_value() != !check.problem.empty(), "a row both taken and refused");
                    if (check.index) check_taken(row, *check.index);
                },
                limits);
        } catch (const InputError&) {
        }
        try {
            const std::string first = read_first_line(rows_path(), limits);
            FUZZ_CHECK(first.size() <= limits.preamble_line_bytes, "a first line of %zu bytes", first.size());
            FUZZ_CHECK(first.find('\n') == std::string::npos, "a first line with its line end");
        } catch (const InputError&) {
        }
    } catch (const std::exception& e) {
        FUZZ_CHECK(false, "unexpected exception: %s", e.what());
    }
    return 0;
}
