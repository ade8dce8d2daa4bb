// Runs independent tasks on a few threads. Which thread runs a task is left to the scheduler,
// so callers write each task's result into its own slot and combine the slots in index order:
// the outcome is then the same for any thread count and any load.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace opgraph {

// The number of hardware threads (at least 1).
inline int HardwareThreads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

// Calls body(i) for every i in [0, count) on up to `num_threads` threads (the caller's among
// them; it runs task 0, so a task that must stay on the calling thread goes first). An
// exception thrown by a task is rethrown here, the one of the lowest index first, after every
// task has ended.
template <typename Body>
void ParallelFor(int count, int num_threads, const Body& body) {
  const int workers = std::max(1, std::min(num_threads, count));
  std::vector<std::exception_ptr> errors(static_cast<size_t>(std::max(count, 0)));
  auto run = [&](int i) {
    try {
      body(i);
    } catch (...) {
      errors[static_cast<size_t>(i)] = std::current_exception();
    }
  };
  std::atomic<int> next{1};
  auto work = [&] {
    for (int i = next++; i < count; i = next++) run(i);
  };
  std::vector<std::thread> threads;
  threads.reserve(static_cast<size_t>(workers - 1));
  for (int t = 1; t < workers; ++t) threads.emplace_back(work);
  if (count > 0) run(0);
  work();
  for (std::thread& thread : threads) thread.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace opgraph
