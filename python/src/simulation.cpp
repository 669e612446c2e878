// Simulation: a scenario made runnable, its frames as numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "common.hpp"
#include "dragon/analyses.hpp"
#include "dragon/chain.hpp"

namespace dragon::python {

namespace {

py::object jam_dict(const std::optional<Jam>& j) {
    if (!j) return py::none();
    py::dict d;
    d["time"] = j->time;
    d["travel"] = j->travel;
    d["handle"] = j->handle;
    d["kind"] = to_string(j->kind);
    d["ahead"] = j->ahead;
    d["point"] = py::make_tuple(j->point.x(), j->point.y());
    d["tolerance"] = j->tolerance;
    return d;
}

// One frame: positions (H, 2), speeds (H,), tangents (H, 2), the benches' rectangles as centres
// (N, 2), axes (N, 2) and half sizes (N, 2); its time and head travel.
py::dict frame_dict(const Simulation& sim, const Frame& f) {
    const auto h = static_cast<py::ssize_t>(f.handles.size());
    const auto n = static_cast<py::ssize_t>(f.benches.size());
    py::array_t<double> pos({h, py::ssize_t{2}}), tan({h, py::ssize_t{2}}), speed(h);
    py::array_t<double> centre({n, py::ssize_t{2}}), axis({n, py::ssize_t{2}}), half({n, py::ssize_t{2}});
    auto p = pos.mutable_unchecked<2>();
    auto t = tan.mutable_unchecked<2>();
    auto v = speed.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < h; ++i) {
        const Handle& hd = f.handles[static_cast<std::size_t>(i)];
        p(i, 0) = hd.pos.x(), p(i, 1) = hd.pos.y();
        t(i, 0) = hd.tangent.x(), t(i, 1) = hd.tangent.y();
        v(i) = hd.speed;
    }
    auto c = centre.mutable_unchecked<2>();
    auto a = axis.mutable_unchecked<2>();
    auto s = half.mutable_unchecked<2>();
    for (py::ssize_t k = 0; k < n; ++k) {
        const Rect& r = f.benches[static_cast<std::size_t>(k)];
        c(k, 0) = r.centre.x(), c(k, 1) = r.centre.y();
        a(k, 0) = r.axis.x(), a(k, 1) = r.axis.y();
        s(k, 0) = r.half_length, s(k, 1) = r.half_width;
    }
    py::dict d;
    d["time"] = f.time;
    d["travel"] = sim.travel(f.time);
    d["positions"] = pos;
    d["speeds"] = speed;
    d["tangents"] = tan;
    d["bench_centres"] = centre;
    d["bench_axes"] = axis;
    d["bench_half_sizes"] = half;
    return d;
}

}  // namespace

py::object jam_object(const std::optional<Jam>& j) { return jam_dict(j); }
py::dict frame_object(const Simulation& sim, const Frame& f) { return frame_dict(sim, f); }

void bind_simulation(py::module_& m) {
    py::class_<Simulation>(m, "_Simulation")
        .def(py::init([](const py::dict& scenario, const std::string& path) {
                 Scenario s = scenario_from(scenario);
                 s.path.kind = path_kind(path);
                 return Simulation(s);
             }),
             py::arg("scenario"), py::arg("path"))
        .def_property_readonly("path", [](const Simulation& sim) { return to_string(sim.scenario().path.kind); })
        .def_property_readonly("scenario", [](const Simulation& sim) { return scenario_dict(sim.scenario()); })
        .def("valid_range",
             [](const Simulation& sim) {
                 const ValidRange r = interruptible([&](Executor&) { return sim.valid_range(); });
                 py::dict d;
                 d["from"] = r.from;
                 d["to"] = r.to;
                 d["from_travel"] = r.from_travel;
                 d["to_travel"] = r.to_travel;
                 d["before"] = jam_dict(r.before);
                 d["after"] = jam_dict(r.after);
                 return d;
             })
        .def("frame",
             [](const Simulation& sim, double t) {
                 Frame f;
                 {
                     py::gil_scoped_release release;
                     sim.frame_into(t, f);
                 }
                 return frame_dict(sim, f);
             },
             py::arg("t"))
        // The frames at `times` straight into new arrays (each frame copied once, on the worker
        // that made it): times (T,), positions (T, H, 2), speeds (T, H).
        .def("frames",
             [](const Simulation& sim, py::array_t<double, py::array::c_style | py::array::forcecast> times, int workers) {
                 if (times.ndim() != 1) throw InputError(Key::times, fmt::format("an array of {} dimensions", times.ndim()),
                                                         "give a sequence of times in seconds");
                 const std::vector<double> ts(times.data(), times.data() + times.size());
                 const auto count = static_cast<py::ssize_t>(ts.size());
                 const auto h = static_cast<py::ssize_t>(sim.solved_benches() + 1);
                 py::array_t<double> pos({count, h, py::ssize_t{2}}), speed({count, h});
                 double* p = pos.mutable_data();
                 double* v = speed.mutable_data();
                 interruptible([&](Executor& ex) {
                     simulate_at(sim, ts, [&](std::size_t k, const Frame& f) {
                         double* pk = p + static_cast<std::ptrdiff_t>(k) * h * 2;
                         double* vk = v + static_cast<std::ptrdiff_t>(k) * h;
                         for (std::size_t i = 0; i < f.handles.size(); ++i) {
                             pk[2 * i] = f.handles[i].pos.x();
                             pk[2 * i + 1] = f.handles[i].pos.y();
                             vk[i] = f.handles[i].speed;
                         }
                     }, &ex);
                 }, workers_from(workers));
                 py::array_t<double> copy(count);
                 std::copy(ts.begin(), ts.end(), copy.mutable_data());
                 return py::make_tuple(copy, pos, speed);
             },
             py::arg("times"), py::arg("workers") = 0)
        .def("time_of", &Simulation::time_of, py::arg("travel"))
        .def("travel", &Simulation::travel, py::arg("t"));
}

}  // namespace dragon::python
