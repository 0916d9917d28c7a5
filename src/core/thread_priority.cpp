#include "core/thread_priority.hpp"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace eco {

void lowerThisThreadsPriority() {
  // On Linux, PRIO_PROCESS with a thread id sets that thread's niceness alone.
  const auto thread = static_cast<id_t>(syscall(SYS_gettid));
  const int current = getpriority(PRIO_PROCESS, thread);
  setpriority(PRIO_PROCESS, thread, current + 10);
}

}  // namespace eco
