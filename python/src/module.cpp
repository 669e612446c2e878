// benchdragon's compiled part, _benchdragon: thin bindings over the library, which builds every
// answer; the package (benchdragon/__init__.py) gives them their Python shapes.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "common.hpp"
#include "dragon/input_files.hpp"
#include "dragon/scenario.hpp"
#include "dragon/sweep.hpp"

namespace dragon::python {
void bind_simulation(py::module_& m);
void bind_answers(py::module_& m);
void bind_sweep(py::module_& m);
void bind_sweep_files(py::module_& m);
void bind_pictures(py::module_& m);
}  // namespace dragon::python

PYBIND11_MODULE(_benchdragon, m) {
    using namespace dragon::python;
    m.doc() = "benchdragon's compiled part: use the benchdragon package";
    register_errors(m);
    m.def("_scenario", [](const py::dict& values) { return scenario_dict(scenario_from(values)); },
          "The scenario of these keyword values over the contest's defaults, each checked; all its values.");
    m.def("_scenario_from_toml",
          [](const std::string& path) {
              py::gil_scoped_release release;
              const dragon::LoadedScenario loaded = dragon::read_scenario_file(path);
              py::gil_scoped_acquire acquire;
              py::dict given;
              const py::dict all = scenario_dict(loaded.scenario);
              for (const dragon::SweepParameter& p : dragon::sweep_parameters())
                  if (loaded.values & p.value) {
                      std::string name = p.name;
                      for (char& c : name)
                          if (c == '-') c = '_';
                      given[name.c_str()] = all[name.c_str()];
                  }
              py::list warnings;
              for (const dragon::KeyWarning& w : loaded.warnings) warnings.append(w.message);
              return py::make_tuple(all, given, warnings);
          },
          "(every value, the values the file set, a message per old name it used) of a scenario file.");
    m.def("_validate",
          [](const py::dict& values, const std::string& path) {
              dragon::Scenario s = scenario_from(values);
              s.path.kind = path_kind(path);
              dragon::validate(s);
          },
          "Checks every value a simulation on this path reads, and the rules between them.");
    bind_simulation(m);
    bind_answers(m);
    bind_sweep(m);
    bind_sweep_files(m);
    bind_pictures(m);
}
