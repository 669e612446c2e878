// A sweep's rows file for Python (dragon/sweep_files.hpp): opened or resumed by the library,
// which says which scenarios are left; Python makes those on its executor and hands the rows back
// to be appended, each made durable as the tool makes it. And a sweep's parts merged.
#include <pybind11/stl.h>

#include <memory>
#include <utility>

#include <fmt/format.h>

#include "common.hpp"
#include "dragon/input_file.hpp"
#include "dragon/sweep_files.hpp"
#include "dragon/sweep_row_check.hpp"

namespace dragon::python {

namespace {

// The library names the rows' file Key::out; here it is sweep()'s and merge_sweep()'s `out`
// (elsewhere a picture's `path`).
template <class F>
auto naming_out(F&& work) {
    try {
        return work();
    } catch (const InputError& e) {
        if (e.key() != Key::out) throw;
        raise_input_error(e, "out");
    }
}

// An open rows' file: the rows it held (when resumed), what resuming found, and the rows left.
class SweepFile {
public:
    SweepFile(const std::string& spec, const std::string& out, bool resume)
        : setup_(read_spec_line(spec, "the sweep's first line")), out_(out) {
        naming_out([&] {
            py::gil_scoped_release release;
            writer_ = std::make_unique<SweepWriter>(
                setup_, SweepOutputRequest{out, resume},
                [&](std::size_t scenario, const std::string& row) { resumed_.emplace_back(scenario, row); },
                [&](const std::string& note) { notes_.push_back(note); });
            return 0;
        });
        written_ = writer_->done();
    }

    // The scenarios of the sweep's part not in the file yet, in the grid's order.
    std::vector<std::size_t> todo() const {
        std::vector<std::size_t> out;
        const std::size_t n = setup_.shard.size(setup_.grid.size());
        for (std::size_t j = 0; j < n; ++j)
            if (!written_[setup_.shard.scenario(j)]) out.push_back(setup_.shard.scenario(j));
        return out;
    }

    // Appends the rows made for `scenarios`, each checked to be that scenario's row of this sweep
    // and not in the file yet (a worker of another version, or a row given twice, is refused
    // before it is written). Returns how many of them note a failed measure.
    std::size_t append(const std::vector<std::size_t>& scenarios, const std::vector<std::string>& rows) {
        if (scenarios.size() != rows.size())
            throw InputError(Key::row, fmt::format("{}", rows.size()), fmt::format("one row per scenario ({})", scenarios.size()));
        py::gil_scoped_release release;
        std::size_t failed = 0;
        for (std::size_t k = 0; k < rows.size(); ++k) {
            const RowCheck check = check_row(setup_, rows[k]);
            if (!check.index || *check.index != scenarios[k] || written_[*check.index])
                throw InputError(Key::row, shown_text(rows[k], 60),
                                 check.index ? fmt::format("scenario {}'s row of this sweep, once", scenarios[k])
                                             : fmt::format("a row of this sweep ({})", check.problem));
            writer_->append(rows[k]);
            written_[*check.index] = true;
            failed += check.failed ? 1 : 0;
        }
        return failed;
    }

    void finish() {
        py::gil_scoped_release release;
        writer_->finish();
    }

    const std::vector<std::pair<std::size_t, std::string>>& resumed() const { return resumed_; }
    const std::vector<std::string>& notes() const { return notes_; }
    std::string partial() const { return partial_path(out_); }  // where the rows stay until finished

private:
    SweepSetup setup_;
    std::string out_;
    std::unique_ptr<SweepWriter> writer_;
    std::vector<bool> written_;
    std::vector<std::pair<std::size_t, std::string>> resumed_;
    std::vector<std::string> notes_;
};

}  // namespace

void bind_sweep_files(py::module_& m) {
    py::class_<SweepFile>(m, "_SweepFile")
        .def(py::init<const std::string&, const std::string&, bool>(), py::arg("spec"), py::arg("out"),
             py::arg("resume"))
        .def("todo", &SweepFile::todo)
        .def("append", &SweepFile::append, py::arg("scenarios"), py::arg("rows"))
        .def("finish", &SweepFile::finish)
        .def_property_readonly("resumed", &SweepFile::resumed)
        .def_property_readonly("notes", &SweepFile::notes)
        .def_property_readonly("partial", &SweepFile::partial);

    // The library's check of where a sweep's rows go, before any work (resume without out).
    m.def("_check_sweep_output", [](const std::string& out, bool resume) {
        naming_out([&] {
            check_sweep_output({out, resume});
            return 0;
        });
    });

    // (the whole sweep's first line, its header, [(scenario, row)] in the files' order): the
    // parts merged into `out`, all-or-nothing.
    m.def("_merge_sweep",
          [](const std::string& out, const std::vector<std::string>& parts) {
              std::vector<std::pair<std::size_t, std::string>> rows;
              SweepSetup whole = naming_out([&] {
                  py::gil_scoped_release release;
                  SweepSetup w = whole_sweep(parts);
                  merge_sweep_parts(w, out, parts,
                                    [&](std::size_t scenario, const std::string& row) { rows.emplace_back(scenario, row); });
                  return w;
              });
              return py::make_tuple(spec_line(whole), header(whole), rows);
          },
          py::arg("out"), py::arg("parts"));
}

}  // namespace dragon::python
