// Runs a number of independent tasks on up to `threads` threads (the caller's among them), each
// task handed the index of the worker that runs it (for that worker's scratch). Which worker
// runs which task varies from run to run, so a result may depend on the tasks, never on the
// workers: the supernodal factor's bits are the same for any number of threads.
#pragma once

#include <atomic>
#include <thread>
#include <vector>

namespace contactbody {

class WorkerTeam {
public:
    explicit WorkerTeam(int threads) : threads_(threads < 1 ? 1 : threads) {}
    int threads() const { return threads_; }
    // task(t, worker) for t = 0 .. tasks - 1; returns when all have run. One task, or one
    // thread, runs on the caller alone.
    template <class Task>
    void run(int tasks, const Task& task) const {
        const int workers = tasks < threads_ ? tasks : threads_;
        if (workers <= 1) {
            for (int t = 0; t < tasks; ++t) task(t, 0);
            return;
        }
        std::atomic<int> next{0};
        const auto work = [&](int worker) {
            for (int t; (t = next.fetch_add(1)) < tasks;) task(t, worker);
        };
        std::vector<std::thread> helpers;
        helpers.reserve(static_cast<size_t>(workers - 1));
        for (int w = 1; w < workers; ++w) helpers.emplace_back(work, w);
        work(0);
        for (std::thread& h : helpers) h.join();
    }

private:
    int threads_;
};

}  // namespace contactbody
