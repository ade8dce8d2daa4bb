#include "core/priority_tasks.h"

#include <algorithm>

#ifdef __linux__
#include <errno.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace opgraph {

int NiceOfTask(int index) {
  constexpr int kNice[] = {0, 10, 15, 19};
  return kNice[std::clamp(index, 0, 3)];
}

void LowerThisThreadsPriority(int nice) {
#ifdef __linux__
  // On Linux a nice value belongs to a thread (its task id), not to the whole process.
  const id_t thread = static_cast<id_t>(syscall(SYS_gettid));
  errno = 0;
  const int current = getpriority(PRIO_PROCESS, thread);
  if (errno == 0 && nice > current) setpriority(PRIO_PROCESS, thread, nice);
#else
  (void)nice;
#endif
}

}  // namespace opgraph
