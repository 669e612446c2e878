#include "dragon/executor.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace dragon {

void InlineExecutor::parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& body) {
    for (std::size_t i = 0; i < count; ++i) {
        check_stop(*this);
        body(i, 0);
    }
}

void StoppableExecutor::parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& body) {
    check_stop(*this);
    inner_.parallel_for(count, [&](std::size_t item, int worker) {
        check_stop(*this);
        body(item, worker);
    });
}

// One job at a time: the items are claimed from an atomic counter by the calling thread (worker
// 0) and the pool's threads (workers 1..n-1), woken by a generation number.
struct ThreadPool::State {
    int workers = 1;
    std::vector<std::thread> threads;
    std::mutex job;  // held by the caller for the whole of a parallel_for
    std::mutex lock; // guards what follows
    std::condition_variable wake, idle;
    std::uint64_t generation = 0;
    bool stop = false;
    int busy = 0;  // pool threads not yet done with the current job
    const std::function<void(std::size_t, int)>* body = nullptr;
    std::size_t count = 0;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr failure;

    void run_items(int worker) {
        for (std::size_t i; !failed.load(std::memory_order_relaxed) && (i = next++) < count;) {
            try {
                (*body)(i, worker);
            } catch (...) {
                const std::lock_guard<std::mutex> hold(lock);
                if (!failure) failure = std::current_exception();
                failed = true;
            }
        }
    }
};

namespace {
// The pool whose job this thread is running, if any: a parallel_for on the same pool from inside
// a body runs inline (waiting for the pool from one of its own workers would deadlock).
thread_local const void* running_job_of = nullptr;
}  // namespace

ThreadPool::ThreadPool(int workers) : state_(std::make_unique<State>()) {
    State& s = *state_;
    s.workers = workers > 0 ? workers : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    for (int k = 1; k < s.workers; ++k) {
        s.threads.emplace_back([&s, k] {
            running_job_of = &s;
            std::uint64_t seen = 0;
            std::unique_lock<std::mutex> l(s.lock);
            for (;;) {
                s.wake.wait(l, [&] { return s.stop || s.generation != seen; });
                if (s.stop) return;
                seen = s.generation;
                l.unlock();
                s.run_items(k);
                l.lock();
                if (--s.busy == 0) s.idle.notify_all();
            }
        });
    }
}

ThreadPool::~ThreadPool() {
    {
        const std::lock_guard<std::mutex> hold(state_->lock);
        state_->stop = true;
    }
    state_->wake.notify_all();
    for (std::thread& t : state_->threads) t.join();
}

int ThreadPool::workers() const { return state_->workers; }

void ThreadPool::parallel_for(std::size_t count, const std::function<void(std::size_t, int)>& body) {
    State& s = *state_;
    if (count == 0) return;
    if (running_job_of == &s || s.threads.empty() || count == 1) {
        for (std::size_t i = 0; i < count; ++i) body(i, 0);
        return;
    }
    const std::lock_guard<std::mutex> one_job(s.job);
    {
        const std::lock_guard<std::mutex> hold(s.lock);
        s.body = &body;
        s.count = count;
        s.next = 0;
        s.failed = false;
        s.failure = nullptr;
        s.busy = static_cast<int>(s.threads.size());
        ++s.generation;
    }
    s.wake.notify_all();
    const void* outer = running_job_of;
    running_job_of = &s;
    s.run_items(0);
    running_job_of = outer;
    std::unique_lock<std::mutex> l(s.lock);
    s.idle.wait(l, [&] { return s.busy == 0; });
    s.body = nullptr;
    if (s.failure) std::rethrow_exception(s.failure);
}

namespace {
std::mutex default_lock;
int default_workers = 0;  // 0: one per core
std::unique_ptr<ThreadPool> default_pool;
}  // namespace

Executor& default_executor() {
    const std::lock_guard<std::mutex> hold(default_lock);
    if (!default_pool) default_pool = std::make_unique<ThreadPool>(default_workers);
    return *default_pool;
}

void set_default_workers(int workers) {
    const std::lock_guard<std::mutex> hold(default_lock);
    if (workers < 1) throw std::invalid_argument("set_default_workers: at least one worker");
    if (default_pool && default_pool->workers() != workers)
        throw std::logic_error("set_default_workers: the default executor is already running");
    default_workers = workers;
}

}  // namespace dragon
