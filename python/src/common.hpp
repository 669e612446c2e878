// What the bindings share: the Python exception types, scenarios to and from Python, and running
// a long call with the GIL released while Ctrl-C can stop it.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>

#include <pybind11/pybind11.h>

#include "dragon/chain.hpp"
#include "dragon/executor.hpp"
#include "dragon/progress.hpp"
#include "dragon/scenario.hpp"
#include "dragon/window.hpp"

namespace dragon::python {

namespace py = pybind11;

// benchdragon.InputError (a ValueError), FileError (an OSError), SolverError (a RuntimeError),
// made in the module and translated from the library's exceptions.
void register_errors(py::module_& m);
// Raises e as benchdragon.InputError naming `field`, the keyword that gave its value where the
// key's usual keyword is not it (a sweep's `out`, a picture's `path`).
[[noreturn]] void raise_input_error(const InputError& e, const std::string& field);

// A scenario from keyword values named as the CLI's flags in snake_case (bench_count=100), over
// the contest's defaults; each value checked on its own range (rules between values are checked
// where a computation reads them, as the tool does). And back.
Scenario scenario_from(const py::dict& values);
py::dict scenario_dict(const Scenario& s);
// "spiral" or "turnaround"; InputError (field "path") otherwise.
PathKind path_kind(const std::string& name);
// A window end from Python: None (the default), a number of seconds, or "12.5s" / "-100m".
std::optional<Along> along_from(const py::object& v, Key field);
// The window over a default: `from_` and `to` as given.
RunWindow window_from(const RunWindow& defaults, const py::object& from, const py::object& to);
// A switch from Python (`prove`): True or False. Anything else, 1 and "yes" among them, is
// refused naming `key`: a switch that silently took any truthy value would run a slow proof,
// or skip one, on a typo.
bool switch_from(const py::object& v, Key key);

// The end of the valid motion as a dict (the answers' "jam" keys), None when unset.
py::object jam_object(const std::optional<Jam>& j);

// A progress callback from Python (or None): called with (done, total), the GIL taken for it.
WorkProgress progress_from(const py::object& callback);

// Runs work(executor) on a thread of its own with the GIL released, while this thread checks
// Python's signals every 50 ms: a KeyboardInterrupt (Ctrl-C, or a notebook's interrupt) asks the
// work to stop (it throws Cancelled at its next check) and is raised here once it has. The
// work runs on a pool made for this call (`workers`, 0: one per core) and joined before it
// returns: nothing is left running between calls, so a process forked afterwards (a
// ProcessPoolExecutor's workers) finds no half-inherited threads.
// `workers` as a Python keyword gives it: 0 (one per core) or a positive count; anything else is
// refused naming the keyword.
int workers_from(int workers);

template <class F>
auto interruptible(F&& work, int workers = 0) -> std::invoke_result_t<F&, Executor&> {
    using R = std::invoke_result_t<F&, Executor&>;
    ThreadPool pool(workers);
    StoppableExecutor ex(pool);
    std::optional<std::conditional_t<std::is_void_v<R>, bool, R>> result;
    std::exception_ptr error;
    std::mutex lock;
    std::condition_variable finished;
    bool done = false, interrupted = false;
    {
        py::gil_scoped_release release;
        std::thread worker([&] {
            try {
                if constexpr (std::is_void_v<R>) {
                    work(ex);
                    result.emplace(true);
                } else {
                    result.emplace(work(ex));
                }
            } catch (...) {
                error = std::current_exception();
            }
            const std::lock_guard<std::mutex> hold(lock);
            done = true;
            finished.notify_all();
        });
        std::unique_lock<std::mutex> l(lock);
        while (!done) {
            if (finished.wait_for(l, std::chrono::milliseconds(50), [&] { return done; })) break;
            l.unlock();
            {
                py::gil_scoped_acquire acquire;
                if (!interrupted && PyErr_CheckSignals() != 0) {
                    interrupted = true;  // the KeyboardInterrupt stays set until raised below
                    ex.request_stop();
                }
            }
            l.lock();
        }
        l.unlock();
        worker.join();
    }
    if (interrupted) throw py::error_already_set();
    if (error) std::rethrow_exception(error);
    if constexpr (!std::is_void_v<R>) return std::move(*result);
}

}  // namespace dragon::python
