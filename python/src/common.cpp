#include "common.hpp"

#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "dragon/chain.hpp"
#include "dragon/errors.hpp"
#include "dragon/sweep.hpp"

namespace dragon::python {

namespace {

py::object input_error, file_error, solver_error;

// The keyword that sets a key: its name, but where Python's words differ (`from` is reserved,
// a moment is `t`, a print size `print_size`, beside the builtin print).
std::string python_name(Key key) {
    switch (key) {
        case Key::from: return "from_";
        case Key::time_range: case Key::clearance_range: return "from_/to";
        case Key::time: return "t";
        case Key::print: return "print_size";
        case Key::out: return "path";  // Picture.save(path), Video.save(path)
        default: return std::string(key_info(key).name);
    }
}

// A Python exception of `type` with the message and the attributes given.
void raise_with(const py::object& type, const std::string& message, const py::dict& attributes) {
    py::object exc = type(message);
    for (const auto& [k, v] : attributes) exc.attr(k) = v;
    PyErr_SetObject(type.ptr(), exc.ptr());
}

}  // namespace

void raise_input_error(const InputError& e, const std::string& field) {
    py::dict a;
    a["field"] = field;
    a["value"] = e.value();
    a["allowed"] = e.allowed();
    a["jam"] = py::none();
    raise_with(input_error, e.what(), a);
    throw py::error_already_set();
}

void register_errors(py::module_& m) {
    const py::object builtins = py::module_::import("builtins");
    const auto make = [&](const char* name, const char* base, const char* doc) {
        py::object type = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
            (std::string("benchdragon.") + name).c_str(), doc, builtins.attr(base).ptr(), nullptr));
        m.attr(name) = type;
        return type;
    };
    input_error = make("InputError", "ValueError",
                       "A value that cannot be used: .field (the keyword that gave it), .value (as given), "
                       ".allowed (what is), and .jam (the end of the valid motion) for a moment past it.");
    file_error = make("FileError", "OSError", "A file that could not be read or written: .filename and .strerror.");
    solver_error = make("SolverError", "RuntimeError", "The computation could not reach an answer (not the input's fault).");
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const PastTheValidMotion& e) {
            py::dict a;
            a["field"] = python_name(e.key());
            a["value"] = e.value();
            a["allowed"] = e.allowed();
            // The package's Jam (a result: keys and attributes), as valid_range gives it.
            a["jam"] = py::module_::import("benchdragon").attr("Jam")(jam_object(e.jam));
            raise_with(input_error, e.what(), a);
        } catch (const InputError& e) {
            const bool one_value = e.key() != Key::none;
            py::dict a;
            a["field"] = one_value ? py::object(py::str(python_name(e.key()))) : py::object(py::none());
            a["value"] = one_value ? py::object(py::str(e.value())) : py::object(py::none());
            a["allowed"] = one_value ? py::object(py::str(e.allowed())) : py::object(py::none());
            a["jam"] = py::none();
            raise_with(input_error, e.what(), a);
        } catch (const FileError& e) {
            // OSError(errno, strerror, filename) sets .strerror and .filename; errno is unknown here.
            py::object exc = file_error(py::none(), e.what(), e.path());
            PyErr_SetObject(file_error.ptr(), exc.ptr());
        } catch (const SolverError& e) {
            PyErr_SetString(solver_error.ptr(), e.what());
        } catch (const Cancelled& e) {
            PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
        }
    });
}

Scenario scenario_from(const py::dict& values) {
    Scenario s;
    ScenarioValues given = 0;
    for (const auto& [key, v] : values) {
        const std::string name = py::str(key);
        const KeyInfo* k = name.find('-') == std::string::npos ? find_key(name) : nullptr;
        const SweepParameter* p = k && k->scenario ? find_sweep_parameter(hyphenated(k->key)) : nullptr;
        if (!p) throw py::type_error(fmt::format("Scenario() got an unexpected keyword argument '{}'", name));
        if (v.is_none()) continue;
        // A bool is not a number here, though Python's True == 1.
        if (py::isinstance<py::bool_>(v))
            throw InputError(k->key, py::str(py::repr(v)).cast<std::string>(), p->whole ? "give a whole number" : "give a number");
        double x;
        if (p->whole && py::isinstance<py::int_>(v)) {
            // Checked as the integer it is, before any narrowing: 2**31 is not -2147483648.
            const py::object n = py::reinterpret_borrow<py::object>(v);
            if (n < py::int_(1) || n > py::int_(kMaxBenchCount)) refuse_bench_count(py::repr(n).cast<std::string>());
            x = static_cast<double>(n.cast<long long>());
        } else {
            try {
                x = v.cast<double>();
            } catch (const py::cast_error&) {
                throw InputError(k->key, py::str(py::repr(v)).cast<std::string>(), p->whole ? "give a whole number" : "give a number");
            }
        }
        if (p->whole && x != std::floor(x))
            throw InputError(k->key, py::str(py::repr(v)).cast<std::string>(), "give a whole number");
        set_parameter(s, *p, x);
        validate(s, p->value);  // the value alone, named as given
        given |= p->value;
    }
    // The rules between the benches' values (the holes within the boards), whatever the path:
    // Scenario(hole_offset=5) is refused here, naming hole_offset. Rules that involve a path's
    // values (the pitch wider than the benches) wait for the path that reads them, as the tool's.
    if (given & value::bench) validate(s, value::bench);
    return s;
}

py::dict scenario_dict(const Scenario& s) {
    py::dict out;
    for (const SweepParameter& p : sweep_parameters()) {
        std::string name = p.name;
        for (char& c : name)
            if (c == '-') c = '_';
        const double v = get_parameter(s, p);
        if (p.whole) out[name.c_str()] = static_cast<long long>(v);
        else out[name.c_str()] = v;
    }
    return out;
}

int workers_from(int workers) {
    // Checked by the package's Python layer (benchdragon._workers), which names the keyword.
    if (workers < 0 || workers > 1024) throw py::value_error(fmt::format("workers={} is not allowed: give 0 (one per core) or 1 to 1024", workers));
    return workers;
}

PathKind path_kind(const std::string& name) {
    if (name == "spiral") return PathKind::spiral;
    if (name == "turnaround") return PathKind::turnaround;
    throw InputError(Key::path, fmt::format("'{}'", name), "use \"spiral\" or \"turnaround\"");
}

std::optional<Along> along_from(const py::object& v, Key field) {
    if (v.is_none()) return std::nullopt;
    if (py::isinstance<py::str>(v)) {
        const std::string text = v.cast<std::string>();
        if (const std::optional<Along> a = parse_along(text)) return a;
        throw InputError(field, fmt::format("'{}'", text),
                         "give a time in seconds (12.5, or \"12.5s\") or head travel in metres (\"-100m\")");
    }
    double x;
    try {
        x = v.cast<double>();
    } catch (const py::cast_error&) {
        throw InputError(field, py::str(py::repr(v)).cast<std::string>(), "give a time in seconds or a string \"-100m\"");
    }
    return Along::seconds(x);
}

RunWindow window_from(const RunWindow& defaults, const py::object& from, const py::object& to) {
    RunWindow w = defaults;
    if (const auto a = along_from(from, Key::from)) w.from = *a;
    if (const auto a = along_from(to, Key::to)) w.to = *a;
    return w;
}

bool switch_from(const py::object& v, Key key) {
    if (!py::isinstance<py::bool_>(v)) throw InputError(key, py::str(py::repr(v)).cast<std::string>(), "give True or False");
    return v.cast<bool>();
}

WorkProgress progress_from(const py::object& callback) {
    if (callback.is_none()) return {};
    // The last copy may be dropped on a worker thread: the object is released holding the GIL.
    std::shared_ptr<py::object> fn(new py::object(callback), [](py::object* o) {
        py::gil_scoped_acquire acquire;
        delete o;
    });
    return [fn](std::int64_t done, std::int64_t total) {
        py::gil_scoped_acquire acquire;
        (*fn)(done, total);
    };
}

}  // namespace dragon::python
