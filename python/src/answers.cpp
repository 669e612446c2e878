// The contest's questions: each the library's analysis and the library's JSON answer (the text
// the tool prints for --json), which Python turns into its result objects.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "common.hpp"
#include "dragon/analyses.hpp"
#include "dragon/answers.hpp"
#include "dragon/atomic_file.hpp"
#include "dragon/contest.hpp"
#include "dragon/contest_files.hpp"
#include "dragon/sweep_setup.hpp"
#include "dragon/tables.hpp"
#include "dragon/turnaround.hpp"

namespace dragon::python {

py::dict frame_object(const Simulation& sim, const Frame& f);


void bind_answers(py::module_& m) {
    // `prove`: every step of the search proved by enclosures, as `dragon collide --prove`; the
    // answer's "enclosure" and "proof" say what was proved either way.
    m.def("_collide",
          [](const py::dict& scenario, const std::string& path, const py::object& from, const py::object& to,
             int workers, const py::object& prove) {
              ContactSearchOptions options;
              options.prove_steps = switch_from(prove, Key::prove);
              Scenario s = scenario_from(scenario);
              s.path.kind = path_kind(path);
              const RunWindow window = window_from(default_window(s.path.kind), from, to);
              const Simulation sim(s);
              const CollideAnswer a = interruptible([&](Executor& ex) {
                  options.executor = &ex;
                  return collide(sim, window, options);
              }, workers_from(workers));
              return py::make_tuple(json_text(collide_answer(a, true)),
                                    a.contact ? py::object(frame_object(sim, a.contact->frame)) : py::none());
          },
          py::arg("scenario"), py::arg("path"), py::arg("from_"), py::arg("to"), py::arg("workers") = 0,
          py::arg("prove") = false);

    m.def("_min_pitch",
          [](const py::dict& scenario, std::optional<double> lo, std::optional<double> hi, double grid,
             const py::object& progress, int workers, const py::object& prove) {
              Scenario s = scenario_from(scenario);
              s.path.kind = PathKind::spiral;
              const PitchRange range = pitch_search_range(s, lo, hi);  // the command's, to the digit
              MinPitchOptions o;
              o.grid = grid;
              o.prove = switch_from(prove, Key::prove);
              o.progress = progress_from(progress);
              const MinPitch mp = interruptible([&](Executor& ex) {
                  o.executor = &ex;
                  return min_pitch(s, range.lo, range.hi, o);
              }, workers_from(workers));
              return json_text(min_pitch_answer(mp, s.path.turn_radius));
          },
          py::arg("scenario"), py::arg("lo"), py::arg("hi"), py::arg("grid"), py::arg("progress"),
          py::arg("workers") = 0, py::arg("prove") = false);

    m.def("_turnaround",
          [](const py::dict& scenario, const py::object& from, const py::object& to, bool clearance,
             const py::object& progress, int workers, const py::object& prove) {
              Scenario s = scenario_from(scenario);
              s.path.kind = PathKind::turnaround;
              const RunWindow window = window_from(kTurnaroundWindow, from, to);
              const WorkProgress report = progress_from(progress);
              const bool proved = switch_from(prove, Key::prove);
              if (proved && !clearance)
                  throw InputError(Key::prove, "True", "it proves the clearance check, which clearance=False leaves out");
              return interruptible([&](Executor& ex) {
                  const TurnaroundStudy st = study_turnaround(s);
                  std::optional<RunClearance> clear;
                  if (clearance) clear = min_clearance(s, window, report, &ex, proved);
                  return json_text(turnaround_answer(st.design, st.design_jam, clear, &st));
              }, workers_from(workers));
          },
          py::arg("scenario"), py::arg("from_"), py::arg("to"), py::arg("clearance"), py::arg("progress"),
          py::arg("workers"), py::arg("prove") = false);

    // `prove`: the largest speed bounded over the whole window, as `dragon max-speed --prove`;
    // the answer's "enclosure" and "proof" say what was proved either way.
    m.def("_max_speed",
          [](const py::dict& scenario, double limit, const py::object& from, const py::object& to, int workers,
             const py::object& prove) {
              MaxSpeedOptions how;
              how.prove = switch_from(prove, Key::prove);
              Scenario s = scenario_from(scenario);
              s.path.kind = PathKind::turnaround;
              const RunWindow window = window_from(kTurnaroundWindow, from, to);
              return interruptible(
                  [&](Executor& ex) {
                      return json_text(max_speed_answer(max_head_speed(s, limit, window, &ex, how), limit));
                  },
                  workers_from(workers));
          },
          py::arg("scenario"), py::arg("limit"), py::arg("from_"), py::arg("to"), py::arg("workers"),
          py::arg("prove") = false);

    // The contest's questions; with `out`, its files as `dragon solve -o out` writes them (all new
    // or all as they were). Returns summary.json's text.
    m.def("_solve",
          [](const py::dict& scenario, const py::object& out, const std::vector<int>& only, const py::object& lo,
             const py::object& hi, double grid, double limit, const py::object& from, const py::object& to,
             int workers, const py::object& prove) {
              const Scenario s = scenario_from(scenario);
              ContestOptions o;
              o.prove = switch_from(prove, Key::prove);
              if (!only.empty()) {
                  o.questions.clear();
                  for (int q : only) {
                      if (q < 1 || q > 5) throw InputError(Key::only, fmt::format("{}", q), "the questions are 1 to 5");
                      o.questions.push_back(static_cast<Question>(q - 1));
                  }
              }
              if (!lo.is_none()) o.pitch_lo = lo.cast<double>();
              if (!hi.is_none()) o.pitch_hi = hi.cast<double>();
              o.pitch_grid = grid;
              o.speed_limit = limit;
              o.turn_window = window_from(kTurnaroundWindow, from, to);
              // The files as dragon solve writes them (the library's ContestFiles): checked before
              // any work, all new or all as they were.
              std::unique_ptr<ContestFiles> files;
              if (!out.is_none()) {
                  files = std::make_unique<ContestFiles>(py::str(out).cast<std::string>(), o);
                  files->attach(o);
              }
              return interruptible([&](Executor& ex) {
                  o.executor = &ex;
                  const ContestAnswers a = solve_contest(s, o);
                  const std::string text = json_text(contest_summary(a, o), 2) + "\n";
                  if (files) files->finish(a, text);
                  return text;
              }, workers_from(workers));
          },
          py::arg("scenario"), py::arg("out"), py::arg("only"), py::arg("lo"), py::arg("hi"), py::arg("grid"),
          py::arg("limit"), py::arg("from_"), py::arg("to"), py::arg("workers"), py::arg("prove") = false);
}

}  // namespace dragon::python
