#include "core/priority_tasks.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#ifdef __linux__
#include <errno.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace opgraph {
namespace {

#ifdef __linux__
int ThisThreadsNice() { return getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid))); }
#endif

TEST(RunInPriorityOrder, RunsEveryTaskOnceAndEachIdleThreadSaysSo) {
  for (int threads : {1, 2, 5}) {
    std::vector<std::atomic<int>> calls(13);
    std::atomic<int> idle{0};
    RunInPriorityOrder(13, threads, [&](int i) { ++calls[i]; }, [&](int) { ++idle; });
    for (const std::atomic<int>& count : calls) EXPECT_EQ(count.load(), 1) << threads << " threads";
    EXPECT_EQ(idle.load(), threads == 1 ? 0 : threads) << threads << " threads";
  }
  RunInPriorityOrder(0, 4, [](int) { FAIL() << "no task to run"; }, [](int) {});
}

#ifdef __linux__
TEST(RunInPriorityOrder, TheCallerRunsTaskZeroAtItsPriorityAndLaterTasksRunLower) {
  const std::thread::id caller = std::this_thread::get_id();
  const int caller_nice = ThisThreadsNice();
  if (caller_nice >= 19) GTEST_SKIP() << "the test runs at the lowest priority already";
  std::vector<int> nice(6, -100);
  std::vector<std::thread::id> ran_on(6);
  RunInPriorityOrder(6, 2, [&](int i) {
    nice[i] = ThisThreadsNice();
    ran_on[i] = std::this_thread::get_id();
  }, [](int) {});
  EXPECT_EQ(ran_on[0], caller);
  EXPECT_EQ(nice[0], caller_nice);
  for (int i = 1; i < 6; ++i) {
    EXPECT_NE(ran_on[i], caller) << i;
    EXPECT_EQ(nice[i], std::max(caller_nice, NiceOfTask(i))) << i;
  }
  EXPECT_EQ(ThisThreadsNice(), caller_nice);  // the caller's own priority is kept
}
#endif

}  // namespace
}  // namespace opgraph
