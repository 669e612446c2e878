#include "cli/sweep_merge.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "dragon/atomic_file.hpp"

namespace dragon::cli {

namespace {

// "width=0.2 body-length=1.6"
std::string describe_scenario(const SweepSetup& setup, std::size_t index) {
    const std::vector<std::string> cells = setup.grid.cells(index);
    std::string out;
    for (std::size_t k = 0; k < cells.size(); ++k)
        out += fmt::format("{}{}={}", k ? " " : "", setup.grid.axes()[k].parameter->name, cells[k]);
    return out;
}

// The lines of a finished rows' file, one at a time; a last line without its line end is an
// error (the file of a run that was killed: resume it first).
class Lines {
public:
    explicit Lines(const std::string& path) : path_(path), in_(path, std::ios::binary) {
        if (!in_ || std::filesystem::is_directory(path)) throw InputError(fmt::format("'{}' cannot be read", path));
    }
    bool next(std::string& line) {
        if (!std::getline(in_, line)) return false;
        if (in_.eof())
            throw InputError(fmt::format("'{}' ends in a torn line: it is the rows of an unfinished run (go on with it "
                                         "with --resume first)", path_));
        ++number_;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        return true;
    }
    std::size_t number() const { return number_; }

private:
    std::string path_;
    std::ifstream in_;
    std::size_t number_ = 0;
};

}  // namespace

SweepSetup whole_sweep(const std::vector<std::string>& parts) {
    if (parts.empty()) throw InputError("dragon sweep merge needs the files to merge: dragon sweep merge OUT.csv PART.csv...");
    Lines first(parts.front());
    std::string line;
    if (!first.next(line)) throw InputError(fmt::format("'{}' is empty: it is not the rows of a dragon sweep", parts.front()));
    return read_spec_line(whole_spec_line(line, parts.front()), parts.front());
}

std::size_t merge_parts(const SweepSetup& whole, const std::string& out, const std::vector<std::string>& parts,
                        const std::function<void(const std::string&)>& on_row) {
    const std::string spec = spec_line(whole), head = csv_line(header(whole));
    const std::size_t naxes = whole.grid.axes().size();
    // Which file holds each scenario (0: none yet): 4 bytes a scenario, the rows never held.
    std::vector<std::uint32_t> owner(whole.grid.size(), 0);
    AtomicFile file(out);
    std::unique_ptr<FILE, int (*)(FILE*)> sink(std::fopen(file.temp_path().c_str(), "wb"), &std::fclose);
    if (!sink) throw file.write_error(std::strerror(errno));
    fmt::print(sink.get(), "{}\n{}\n", spec, head);
    std::size_t rows = 0;
    for (std::size_t f = 0; f < parts.size(); ++f) {
        const std::string& path = parts[f];
        std::error_code same_error;
        if (std::filesystem::equivalent(path, out, same_error))
            throw InputError(fmt::format("'{}' is both the merged file and a part: give the merged file another name", path));
        Lines in(path);
        std::string line;
        if (!in.next(line) || whole_spec_line(line, path) != spec)
            throw InputError(fmt::format("'{}' is not a part of the sweep of '{}': its first line (what the sweep is) "
                                         "differs", path, parts.front()));
        if (!in.next(line) || line != head)
            throw InputError(fmt::format("'{}' is not a part of the sweep of '{}': its header differs", path, parts.front()));
        while (in.next(line)) {
            const std::vector<std::string> fields = split_csv(line);
            const std::optional<std::size_t> index =
                fields.size() < naxes ? std::nullopt
                                      : whole.grid.index_of(std::vector<std::string>(fields.begin(), fields.begin() + static_cast<long>(naxes)));
            if (!index)
                throw InputError(fmt::format("line {} of '{}' is no scenario of this sweep: {:.80}", in.number(), path, line));
            if (owner[*index] != 0)
                throw InputError(fmt::format("the scenario {} is there twice: in '{}' and in '{}' (line {})",
                                             describe_scenario(whole, *index), parts[owner[*index] - 1], path, in.number()));
            owner[*index] = static_cast<std::uint32_t>(f + 1);
            fmt::print(sink.get(), "{}\n", line);
            on_row(line);
            ++rows;
        }
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

}  // namespace dragon::cli
