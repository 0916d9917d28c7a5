#include "core/thread_priority.hpp"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <thread>

#include <gtest/gtest.h>

namespace eco {
namespace {

int niceness() {
  return getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)));
}

}  // namespace

TEST(ThreadPriority, LowersOnlyTheCallingThread) {
  const int before = niceness();
  int inside = 0, started = 0;
  std::thread worker([&] {
    started = niceness();
    lowerThisThreadsPriority();
    inside = niceness();
  });
  worker.join();
  EXPECT_EQ(inside, std::min(started + 10, 19));  // nice values stop at 19
  EXPECT_EQ(niceness(), before);
}

}  // namespace eco
