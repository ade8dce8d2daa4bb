// Runs tasks in priority order on a few threads: task 0 on the calling thread at its own
// priority, the others on threads whose scheduling priority falls with the task's index (on
// Linux, a nice value per thread). For speculative work, where the tasks are ranked by how
// surely their results will be used: a later task then takes a core mostly when the earlier
// ones leave it idle. The priorities change when a task runs, never what it computes.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace opgraph {

// The nice value of task `index`: 0 for the first, then 10, 15 and 19 (the lowest) from the
// fourth on.
int NiceOfTask(int index);

// Lowers the calling thread's scheduling priority to `nice` (never raises it: an unprivileged
// thread cannot). A no-op where per-thread priorities are not available.
void LowerThisThreadsPriority(int nice);

// Calls body(i) for every i in [0, count) on up to `num_threads` threads, task i at priority
// NiceOfTask(i); tasks start in index order. The calling thread runs task 0 only (so its own
// priority is kept), and a new thread takes its place when tasks are left to start. A thread
// that finds no task left to start calls on_idle(i) with the last task it ran, then ends. With
// one thread, the caller runs every task in order at its own priority. An exception thrown by
// a task is rethrown here, the lowest index first, after every task has ended.
template <typename Body, typename Idle>
void RunInPriorityOrder(int count, int num_threads, const Body& body, const Idle& on_idle) {
  if (count <= 0) return;
  std::vector<std::exception_ptr> errors(static_cast<size_t>(count));
  auto run = [&](int i) {
    try {
      body(i);
    } catch (...) {
      errors[static_cast<size_t>(i)] = std::current_exception();
    }
  };
  const int workers = std::max(1, std::min(num_threads, count));
  if (workers == 1) {
    for (int i = 0; i < count; ++i) run(i);
  } else {
    std::atomic<int> next{1};
    auto take_tasks = [&](int i) {
      int last = i;
      for (; i < count; i = next++) {
        LowerThisThreadsPriority(NiceOfTask(i));
        run(i);
        last = i;
      }
      on_idle(last);
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < workers; ++t) threads.emplace_back(take_tasks, next++);
    run(0);
    const int after_first = next++;
    if (after_first < count) {
      threads.emplace_back(take_tasks, after_first);
    } else {
      on_idle(0);
    }
    for (std::thread& thread : threads) thread.join();
  }
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace opgraph
