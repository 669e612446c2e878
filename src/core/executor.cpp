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

int cores() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

namespace {

// One parallel_for: its items are claimed from an atomic counter by its caller and by any pool
// thread that visits it.
struct Job {
    const std::function<void(std::size_t, int)>* body = nullptr;
    std::size_t count = 0;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr failure;  // the first, guarded by State::lock
    int visitors = 0;            // pool threads inside run_items, guarded by State::lock
};

// Which pool this thread belongs to and its number there: a job it starts on that pool is run
// under its own number, so that no two threads of one job share a worker's scratch.
thread_local const void* own_pool = nullptr;
thread_local int own_number = 0;

}  // namespace

struct ThreadPool::State {
    int workers = 1;
    std::vector<std::thread> threads;
    std::mutex lock;  // guards jobs, stop and every Job's failure and visitors
    std::condition_variable wake;  // a job was posted, or the pool stops
    std::condition_variable left;  // a visitor left a job
    std::vector<Job*> jobs;        // posted and not yet fully claimed, newest last
    bool stop = false;

    void run_items(Job& job, int worker) {
        for (std::size_t i; !job.failed.load(std::memory_order_relaxed) && (i = job.next++) < job.count;) {
            try {
                (*job.body)(i, worker);
            } catch (...) {
                const std::lock_guard<std::mutex> hold(lock);
                if (!job.failure) job.failure = std::current_exception();
                job.failed = true;
            }
        }
    }

    // Takes `job` off the list of jobs with items to claim (called with `lock` held).
    void retire(const Job* job) {
        const auto it = std::find(jobs.begin(), jobs.end(), job);
        if (it != jobs.end()) jobs.erase(it);
    }

    void serve(int number) {
        own_pool = this;
        own_number = number;
        std::unique_lock<std::mutex> l(lock);
        for (;;) {
            wake.wait(l, [&] { return stop || !jobs.empty(); });
            if (stop) return;
            // The newest first: a job started inside another's item is the one its caller, busy
            // in that item, waits for.
            Job* job = jobs.back();
            ++job->visitors;
            l.unlock();
            run_items(*job, number);
            l.lock();
            retire(job);  // every item is claimed now
            if (--job->visitors == 0) left.notify_all();
        }
    }
};

ThreadPool::ThreadPool(int workers) : state_(std::make_unique<State>()) {
    State& s = *state_;
    s.workers = workers > 0 ? workers : cores();
    s.threads.reserve(static_cast<std::size_t>(s.workers - 1));
    for (int k = 1; k < s.workers; ++k) s.threads.emplace_back([&s, k] { s.serve(k); });
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
    const int number = own_pool == &s ? own_number : 0;
    if (count == 0) return;
    if (s.threads.empty() || count == 1) {
        for (std::size_t i = 0; i < count; ++i) body(i, number);
        return;
    }
    Job job;
    job.body = &body;
    job.count = count;
    {
        const std::lock_guard<std::mutex> hold(s.lock);
        s.jobs.push_back(&job);
    }
    s.wake.notify_all();
    s.run_items(job, number);
    std::unique_lock<std::mutex> l(s.lock);
    s.retire(&job);  // no new visitor from here on; those inside finish the items they claimed
    s.left.wait(l, [&] { return job.visitors == 0; });
    if (job.failure) std::rethrow_exception(job.failure);
}

}  // namespace dragon
