#include "common.hpp"

#include <cmath>
#include <map>
#include <memory>

#include <fmt/format.h>

#include "dragon/chain.hpp"
#include "dragon/errors.hpp"
#include "dragon/sweep.hpp"

namespace dragon::python {

namespace {

py::object input_error, file_error, solver_error;

// The Python name of a value the library names (a scenario value as its keyword, an option as
// the keyword of the call that takes it).
std::string python_name(const std::string& field) {
    static const std::map<std::string, std::string> names = {
        {"time range start", "from_"},      {"time range end", "to"},
        {"time range", "from_/to"},         {"clearance time range", "from_/to"},
        {"time", "t"},                      {"time step", "step"},
        {"head travel", "travel"},          {"pitch grid", "grid"},
        {"pitch search range end", "hi"},   {"speed limit", "limit"},
        {"picture size", "size"},           {"frame rate", "fps"},
        {"speedup", "speedup"},             {"hold", "hold"},
        {"film moment", "at"},              {"H.264 quality (crf)", "crf"},
        {"VP9 quality (crf)", "crf"},       {"GIF quality (crf)", "crf"},
        {"encoder preset", "preset"},       {"encoder tune", "tune"},
        {"palette colours", "colours"},     {"encoder threads", "threads"},
        {"measure", "measure"},             {"sweep axis", "vary"},
        {"path", "path"},                   {"head speed", "speed"},
        {"video size", "size"},             {"zoom", "zoom"},
        {"language", "lang"},              {"print width", "width_in"},
        {"font size", "font_pt"},           {"dpi", "dpi"},
        {"print size", "print_size"},
    };
    if (const auto it = names.find(field); it != names.end()) return it->second;
    std::string out = field;
    for (char& c : out)
        if (c == ' ' || c == '-') c = '_';
    return out;
}

// A scenario's refusal names its value in words ("pitch = 0 is not allowed: ..."): the keyword
// of the first value involved, the value as written, and what is allowed.
void scenario_fields(const ScenarioError& e, std::string& field, std::string& value, std::string& allowed) {
    for (const SweepParameter& p : sweep_parameters())
        if (e.values & p.value) {
            field = p.name;
            for (char& c : field)
                if (c == '-') c = '_';
            if (field == "head_speed") field = "speed";
            break;
        }
    const std::string what = e.what();
    const std::size_t cut = what.find(" is not allowed");
    if (cut == std::string::npos) return;
    std::string head = what.substr(0, cut);
    const std::size_t eq = head.rfind(" = ");
    value = eq != std::string::npos ? head.substr(eq + 3) : head.substr(head.rfind(' ') + 1);
    const std::size_t colon = what.find(": ", cut);
    allowed = colon != std::string::npos ? what.substr(colon + 2) : "";
}

// A Python exception of `type` with the message and the attributes given.
void raise_with(const py::object& type, const std::string& message, const py::dict& attributes) {
    py::object exc = type(message);
    for (const auto& [k, v] : attributes) exc.attr(k) = v;
    PyErr_SetObject(type.ptr(), exc.ptr());
}

}  // namespace

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
            a["field"] = python_name(e.field());
            a["value"] = e.value();
            a["allowed"] = e.allowed();
            // The package's Jam (a result: keys and attributes), as valid_range gives it.
            a["jam"] = py::module_::import("benchdragon").attr("Jam")(jam_object(e.jam));
            raise_with(input_error, e.what(), a);
        } catch (const ScenarioError& e) {
            std::string field, value, allowed;
            scenario_fields(e, field, value, allowed);
            py::dict a;
            a["field"] = field;
            a["value"] = value;
            a["allowed"] = allowed;
            a["jam"] = py::none();
            raise_with(input_error, e.what(), a);
        } catch (const InputError& e) {
            py::dict a;
            a["field"] = e.field().empty() ? py::object(py::none()) : py::object(py::str(python_name(e.field())));
            a["value"] = e.field().empty() ? py::object(py::none()) : py::object(py::str(e.value()));
            a["allowed"] = e.field().empty() ? py::object(py::none()) : py::object(py::str(e.allowed()));
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
    for (const auto& [key, v] : values) {
        std::string name = py::str(key);
        std::string flag = name == "speed" ? "speed" : name;
        for (char& c : flag)
            if (c == '_') c = '-';
        const SweepParameter* p = find_sweep_parameter(flag);
        if (!p) throw py::type_error(fmt::format("Scenario() got an unexpected keyword argument '{}'", name));
        if (v.is_none()) continue;
        double x;
        try {
            x = v.cast<double>();
        } catch (const py::cast_error&) {
            throw InputError(name, py::str(py::repr(v)).cast<std::string>(), "give a number");
        }
        if (p->whole && !(x == std::floor(x) && std::abs(x) < 9.2e18))
            throw InputError(name, fmt::format("{}", x), "give a whole number");
        set_parameter(s, *p, x);
        validate(s, p->value);
    }
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

PathKind path_kind(const std::string& name) {
    if (name == "spiral") return PathKind::spiral;
    if (name == "turnaround") return PathKind::turnaround;
    throw InputError("path", fmt::format("'{}'", name), "use \"spiral\" or \"turnaround\"");
}

std::optional<Along> along_from(const py::object& v, const char* field) {
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
    if (const auto a = along_from(from, "from_")) w.from = *a;
    if (const auto a = along_from(to, "to")) w.to = *a;
    return w;
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
