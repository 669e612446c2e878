// Sweeps: the library sets a sweep up and makes its rows; Python spreads the rows over any
// concurrent.futures.Executor. A worker needs only the sweep's first line and the rows' indices,
// both picklable text and numbers, so a process pool or a Dask cluster can make rows too.
#include <pybind11/stl.h>

#include <fmt/format.h>

#include "common.hpp"
#include "dragon/sweep_setup.hpp"

namespace dragon::python {

void bind_sweep(py::module_& m) {
    // (first line, header, scenario count, K, N) of a sweep, or of its part K of N: vary as
    // NAME=VALUES specs (names as the CLI's flags), measures, the fixed values as Scenario
    // keywords, the options, and the shard ("K/N", or "" for the whole sweep).
    m.def("_sweep_setup",
          [](const std::vector<std::string>& vary, const std::vector<std::string>& measures, const py::dict& fixed,
             const py::object& lo, const py::object& hi, const py::object& grid, const py::object& limit,
             const py::object& from, const py::object& to, const std::string& shard) {
              SweepAsked asked;
              asked.vary = vary;
              asked.measures = measures;
              const auto text = [](const py::object& v) -> std::optional<std::string> {
                  if (v.is_none()) return std::nullopt;
                  return py::str(v).cast<std::string>();
              };
              asked.lo = text(lo);
              asked.hi = text(hi);
              if (!grid.is_none()) asked.grid = grid.cast<double>();
              if (!limit.is_none()) asked.limit = limit.cast<double>();
              asked.from = text(from);
              asked.to = text(to);
              asked.shard = shard;
              const Scenario given = scenario_from(fixed);
              for (const auto& [key, v] : fixed) {
                  std::string flag = py::str(key);
                  for (char& c : flag)
                      if (c == '_') c = '-';
                  if (const SweepParameter* p = find_sweep_parameter(flag); p && !v.is_none()) asked.fixed_given |= p->value;
              }
              const SweepWords words{[](const char* option) { return std::string(option); },
                                     [](const char* value) {
                                         std::string name = value;
                                         for (char& c : name)
                                             if (c == '-') c = '_';
                                         return fmt::format("fixed['{}']", name);
                                     }};
              const SweepSetup setup = make_sweep_setup(asked, words, [&](ScenarioValues fixed_values, const std::string& why) {
                  const ScenarioValues stray = asked.fixed_given & ~fixed_values;
                  for (const SweepParameter& p : sweep_parameters())
                      if (stray & p.value) {
                          std::string name = p.name;
                          for (char& c : name)
                              if (c == '-') c = '_';
                          throw InputError(fmt::format("fixed['{}'] is not used: {}", name, why));
                      }
                  validate(given, fixed_values);
                  return given;
              });
              return py::make_tuple(spec_line(setup), header(setup), setup.grid.size(), setup.shard.index,
                                    setup.shard.count);
          },
          py::arg("vary"), py::arg("measures"), py::arg("fixed"), py::arg("lo"), py::arg("hi"), py::arg("grid"),
          py::arg("limit"), py::arg("from_"), py::arg("to"), py::arg("shard") = "");

    // The CSV lines of the rows at `indices` of the sweep whose first line is `spec`, made on the
    // calling thread with the GIL released (Ctrl-C stops it between rows and inside them). `stop`,
    // if given, is asked between rows (a sweep on Python threads stops them all this way).
    m.def("_sweep_rows",
          [](const std::string& spec, const std::vector<std::size_t>& indices, const py::object& stop) {
              const SweepSetup setup = read_spec_line(spec, "the sweep's first line");
              return interruptible([&](Executor& ex) {
                  SweepSetup s = setup;
                  InlineExecutor inline_stop(&ex);
                  s.options.stop_source = &inline_stop;
                  std::vector<std::string> lines;
                  lines.reserve(indices.size());
                  for (std::size_t index : indices) {
                      if (index >= s.grid.size())
                          throw InputError(Key::row, fmt::format("{}", index), fmt::format("the sweep has {} rows", s.grid.size()));
                      check_stop(ex);
                      if (!stop.is_none()) {
                          py::gil_scoped_acquire acquire;
                          if (stop().cast<bool>()) throw Cancelled();
                      }
                      lines.push_back(make_row(s, index).csv);
                  }
                  return lines;
              });
          },
          py::arg("spec"), py::arg("indices"), py::arg("stop") = py::none());
}

}  // namespace dragon::python
