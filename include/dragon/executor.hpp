// The threads the library's parallel work runs on, chosen by the caller.
//
// Work comes as a parallel_for: `count` items, handed out to the executor's workers in any
// order; each call gets the item's index and the number of the worker running it (0 ..
// workers() - 1), so that a caller can keep one scratch workspace per worker instead of
// thread-locals. The library starts no threads of its own: every function that runs in parallel
// takes an Executor, or uses default_executor() when given none.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>

namespace dragon {

class Executor {
public:
    virtual ~Executor() = default;
    // How many items may run at once (at least 1).
    virtual int workers() const = 0;
    // Calls body(item, worker) for every item in [0, count), each exactly once, and returns when
    // all are done. The first exception a body throws is rethrown here, once the items already
    // started have finished (the rest are skipped). A parallel_for called from inside a body
    // runs inline on that worker.
    virtual void parallel_for(std::size_t count, const std::function<void(std::size_t item, int worker)>& body) = 0;
};

// Everything on the calling thread, in order: one worker.
class InlineExecutor final : public Executor {
public:
    int workers() const override { return 1; }
    void parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& body) override;
};

// A fixed set of threads, started once and kept; the calling thread works as one of them, so
// ThreadPool(1) starts none. 0: one worker per core.
class ThreadPool final : public Executor {
public:
    explicit ThreadPool(int workers = 0);
    ~ThreadPool() override;
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;
    int workers() const override;
    void parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& body) override;

private:
    struct State;
    std::unique_ptr<State> state_;
};

// The executor used when a caller passes none: a ThreadPool with one worker per core, made on
// first use. set_default_workers(n) before that first use sets its size instead (n >= 1); it
// throws std::logic_error once the pool exists.
Executor& default_executor();
void set_default_workers(int workers);

// `executor`, or default_executor() when it is null.
inline Executor& executor_or_default(Executor* executor) { return executor ? *executor : default_executor(); }

}  // namespace dragon
