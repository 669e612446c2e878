// A sweep's parts joined into one file (dragon/sweep_files.hpp).
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"
#include "dragon/input_file.hpp"
#include "dragon/sweep_files.hpp"
#include "dragon/sweep_row_check.hpp"

namespace dragon {

namespace {

// "width=0.2 body-length=1.6"
std::string describe_scenario(const SweepSetup& setup, std::size_t index) {
    const std::vector<std::string> cells = setup.grid.cells(index);
    std::string out;
    for (std::size_t k = 0; k < cells.size(); ++k)
        out += fmt::format("{}{}={}", k ? " " : "", setup.grid.axes()[k].parameter->name, cells[k]);
    return out;
}

// A part's limits, read as one of the run's inputs.
RowFileLimits part_limits(const SweepSetup& whole, RunOutputs* outputs) {
    RowFileLimits limits = row_limits(whole, "sweep part");
    limits.outputs = outputs;
    return limits;
}

}  // namespace

SweepSetup whole_sweep(const std::vector<std::string>& parts, RunOutputs* outputs) {
    if (parts.empty()) throw InputError("a merge needs the files to merge: give at least one part");
    // The first line is all it takes; merge_sweep_parts reads the rest.
    const std::string spec = read_first_line(parts.front(), {"sweep part", false, outputs});
    return read_spec_line(whole_spec_line(spec, parts.front()), parts.front());
}

std::size_t merge_sweep_parts(const SweepSetup& whole, const std::string& out, const std::vector<std::string>& parts,
                              const SweepRowHeard& on_row, RunOutputs* outputs) {
    if (extension_of(out) != ".csv")
        throw InputError(Key::out, out, fmt::format("a merged sweep is written as .csv (it has extension '{}')",
                                                    extension_of(out)));
    const std::string spec = spec_line(whole), head = csv_line(header(whole));
    // Which file holds each scenario (0: none yet): 4 bytes a scenario, the rows never held.
    std::vector<std::uint32_t> owner(whole.grid.size(), 0);
    AtomicFile file(out, outputs);
    std::unique_ptr<FILE, int (*)(FILE*)> sink(std::fopen(file.temp_path().c_str(), "wb"), &std::fclose);
    if (!sink) throw file.write_error(std::strerror(errno));
    fmt::print(sink.get(), "{}\n{}\n", spec, head);
    std::size_t rows = 0;
    for (std::size_t f = 0; f < parts.size(); ++f) {
        const std::string& path = parts[f];
        std::error_code same_error;
        if (std::filesystem::equivalent(path, out, same_error))
            throw InputError(fmt::format("'{}' is both the merged file and a part: give the merged file another name", path));
        std::size_t number = 2;  // the line number of the row being read
        const RowFileScan scan = scan_row_file(
            path, 2,
            [&](const std::vector<std::string>& preamble) {
                // Its own shard aside, a part's first line is the whole sweep's.
                std::string found = preamble[0];
                try {
                    found = whole_spec_line(preamble[0], path);
                } catch (const InputError&) {
                }
                if (found != spec)
                    throw InputError(fmt::format("'{}' is not a part of the sweep of '{}': {}", shown_text(path, 4096),
                                                 shown_text(parts.front(), 4096), spec_difference(found, spec)));
                if (preamble[1] != head)
                    throw InputError(fmt::format("'{}' is not a part of the sweep of '{}': its header (line 2) differs",
                                                 shown_text(path, 4096), shown_text(parts.front(), 4096)));
            },
            [&](const std::string& line) {
                ++number;
                const RowCheck check = check_row(whole, line);
                const std::optional<std::size_t> index = check.index;
                if (!index)
                    throw InputError(fmt::format("line {} of '{}' is not a row of this sweep: {}: {}", number,
                                                 shown_text(path, 4096), check.problem, shown_text(line, 60)));
                if (owner[*index] != 0)
                    throw InputError(fmt::format("the scenario {} is there twice: in '{}' and in '{}' (line {})",
                                                 describe_scenario(whole, *index), parts[owner[*index] - 1], path, number));
                owner[*index] = static_cast<std::uint32_t>(f + 1);
                fmt::print(sink.get(), "{}\n", line);
                if (on_row) on_row(*index, line);
                ++rows;
            },
            part_limits(whole, outputs));
        if (scan.torn)
            throw InputError(fmt::format("'{}' ends in a torn line: it is the rows of an unfinished run (resume it "
                                         "first)", path));
    }
    std::size_t missing = 0, first = 0;
    for (std::size_t i = owner.size(); i-- > 0;)
        if (owner[i] == 0) ++missing, first = i;
    if (missing > 0)
        throw InputError(fmt::format("{} of the sweep's {} scenarios {} missing, the first: {}; merge every part of the "
                                     "sweep", missing, whole.grid.size(), missing == 1 ? "is" : "are",
                                     describe_scenario(whole, first)));
    if (std::ferror(sink.get()) || std::fclose(sink.release()) != 0) throw file.write_error(std::strerror(errno));
    file.commit();
    return rows;
}

}  // namespace dragon
