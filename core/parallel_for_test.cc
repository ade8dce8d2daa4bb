#include "core/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
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

TEST(ParallelFor, RethrowsTheLowestIndexErrorAfterAllTasks) {
  std::atomic<int> ran{0};
  try {
    ParallelFor(20, 3, [&](int i) {
      ++ran;
      if (i == 7 || i == 13) throw std::runtime_error("task " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), "task 7");
  }
  EXPECT_EQ(ran.load(), 20);
}

}  // namespace
}  // namespace opgraph
