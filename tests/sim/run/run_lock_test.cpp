#include "sim/run/run_lock.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

TEST(RunLock, ASecondRunIntoTheFolderIsRefusedUntilTheFirstEnds) {
  const auto folder = test::freshDirectory("run_lock");
  EXPECT_FALSE(runIsActive(folder));
  {
    RunLock first(folder);
    // flock locks belong to open files: a second open in this process conflicts as one in
    // another process would.
    try {
      RunLock second(folder);
      FAIL() << "two runs held the folder";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what())
                    .find("another ecoforest run (process " + std::to_string(getpid()) + ")"),
                std::string::npos)
          << error.what();
    }
    EXPECT_TRUE(runIsActive(folder));
  }
  EXPECT_FALSE(runIsActive(folder));
  RunLock again(folder);  // released with the first
}

TEST(RunLock, AKilledHolderReleasesTheLock) {
  const auto folder = test::freshDirectory("run_lock_killed");
  const pid_t child = fork();
  if (child == 0) {
    RunLock held(folder);
    pause();  // until killed
    _exit(0);
  }
  for (int i = 0; i < 500 && !runIsActive(folder); ++i) usleep(10000);
  EXPECT_TRUE(runIsActive(folder));
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  EXPECT_FALSE(runIsActive(folder));
  RunLock mine(folder);
}

}  // namespace
}  // namespace eco
