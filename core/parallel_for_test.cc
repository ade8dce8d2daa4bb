#include "core/parallel_for.h"
#include "core/priority_tasks.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace opgraph {
namespace {

TEST(ParallelFor, RunsEveryTaskOnceForAnyThreadCount) {
  for (int threads : {1, 2, 5}) {
    std::vector<std::atomic<int>> calls(37);
    ParallelFor(37, threads, [&](int i) { ++calls[i]; });
    for (const std::atomic<int>& count : calls) EXPECT_EQ(count.load(), 1) << threads << " threads";
  }
  ParallelFor(0, 4, [](int) { FAIL() << "no task to run"; });
}

TEST(ParallelFor, TheCallersThreadRunsTaskZero) {
  const std::thread::id caller = std::this_thread::get_id();
  for (int threads : {1, 2, 4}) {
    for (int attempt = 0; attempt < 20; ++attempt) {
      std::thread::id first;
      ParallelFor(8, threads, [&](int i) {
        if (i == 0) first = std::this_thread::get_id();
      });
      EXPECT_EQ(first, caller) << threads << " threads";
    }
  }
}

// Both task runners (core/priority_tasks.h too) end every task before rethrowing.
TEST(ParallelFor, EitherRunnerRethrowsTheLowestIndexErrorAfterAllTasks) {
  for (const bool by_priority : {false, true}) {
    std::atomic<int> ran{0};
    auto body = [&](int i) {
      ++ran;
      if (i == 7 || i == 13) throw std::runtime_error("task " + std::to_string(i));
    };
    try {
      if (by_priority) {
        RunInPriorityOrder(20, 3, body, [](int) {});
      } else {
        ParallelFor(20, 3, body);
      }
      FAIL() << "no exception";
    } catch (const std::runtime_error& error) {
      EXPECT_EQ(std::string(error.what()), "task 7");
    }
    EXPECT_EQ(ran.load(), 20) << (by_priority ? "RunInPriorityOrder" : "ParallelFor");
  }
}

}  // namespace
}  // namespace opgraph
