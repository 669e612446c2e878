// The threads the library's parallel work runs on, chosen by the caller.
//
// Work comes as a parallel_for: `count` items, handed out to the executor's workers in any
// order; each call gets the item's index and the number of the worker running it (0 ..
// workers() - 1), so that a caller can keep one scratch workspace per worker instead of
// thread-locals. The library starts no threads of its own and keeps no pool: every function that
// runs in parallel takes an Executor from its caller, and given none it runs on the calling
// thread. A pool belongs to whoever made it, so a process that forks after its pools are gone
// (Python's multiprocessing, a server that forks workers) finds nothing half-inherited.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>

namespace dragon {

// A computation its caller stopped (StoppableExecutor::request_stop, a host's Ctrl-C): neither
// the input's fault nor the solver's. Nothing it would have written is left behind.
class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("stopped by the caller") {}
};

// Where the library's parallel work runs: the caller's threads, behind this interface (given
// none, the library runs on the calling thread).
class Executor {
public:
    virtual ~Executor() = default;
    // Whether the caller wants the work stopped. parallel_for then throws Cancelled before
    // starting another item, and the library's long serial loops ask between their units of
    // work (check_stop). Never, unless the executor says otherwise.
    virtual bool stop_requested() const { return false; }
    // How many items may run at once (at least 1).
    virtual int workers() const = 0;
    // Calls body(item, worker) for every item in [0, count), each exactly once, and returns when
    // all are done. The first exception a body throws is rethrown here, once the items already
    // started have finished (the rest are skipped). A parallel_for may be called from inside a
    // body (its items may then run on the other workers too) and from several threads at once.
    virtual void parallel_for(std::size_t count, const std::function<void(std::size_t item, int worker)>& body) = 0;
};

// Everything on the calling thread, in order: one worker. Work nested inside another executor's
// item runs here, and stops when that executor would (`outer`).
class InlineExecutor final : public Executor {
public:
    InlineExecutor() = default;                                         // stops never
    explicit InlineExecutor(const Executor* outer) : outer_(outer) {}  // stops when `outer` would
    int workers() const override { return 1; }
    bool stop_requested() const override { return outer_ && outer_->stop_requested(); }
    // As Executor::parallel_for.
    void parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& body) override;

private:
    const Executor* outer_ = nullptr;
};

// A fixed set of threads, started with the pool and joined when it is destroyed; the calling
// thread works as one of them, so ThreadPool(1) starts none. 0: one worker per core.
//
// Jobs do not wait for each other: a parallel_for started inside another's item (solve's
// minimum-pitch search inside its list of questions), or by another thread at the same time,
// is one more job whose items any idle worker takes. A caller waits only for items that are
// running, and those never wait for items not yet started, so nesting cannot deadlock.
// Worker numbers stay unique within each job: the pool's threads are 1 .. workers() - 1, and a
// job's caller is 0, or its own number when it is one of the pool's threads.
class ThreadPool final : public Executor {
public:
    explicit ThreadPool(int workers = 0);  // starts workers - 1 threads (0: one worker per core)
    ~ThreadPool() override;
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;
    int workers() const override;
    // As Executor::parallel_for.
    void parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& body) override;

private:
    struct State;
    std::unique_ptr<State> state_;
};

// Another executor's workers, and a way to stop: request_stop() (from any thread) makes the work
// running on it throw Cancelled at its next item or check. For a host that lets its user
// interrupt (Python's Ctrl-C).
class StoppableExecutor final : public Executor {
public:
    explicit StoppableExecutor(Executor& inner) : inner_(inner) {}  // runs on `inner`'s workers
    void request_stop() { stop_ = true; }                             // from any thread
    bool stop_requested() const override { return stop_.load(std::memory_order_relaxed); }
    int workers() const override { return inner_.workers(); }
    // As Executor::parallel_for.
    void parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& body) override;

private:
    Executor& inner_;
    std::atomic<bool> stop_{false};
};

// Throws Cancelled if `ex` asks to stop: long serial loops call it between their units of work.
inline void check_stop(const Executor& ex) {
    if (ex.stop_requested()) throw Cancelled();
}

// `executor`, or `serial` (the calling thread) when it is null: what a function given no
// executor runs on. Keeps no state: the caller owns both.
inline Executor& executor_or(Executor* executor, InlineExecutor& serial) { return executor ? *executor : serial; }

// How many workers "one per core" means here (at least 1).
int cores();

}  // namespace dragon
