#include "core/interrupt.hpp"

#include <sys/wait.h>
#include <unistd.h>
#include <csignal>

#include <gtest/gtest.h>

#include "core/atomic_file.hpp"
#include "test_files.hpp"

namespace eco {
using test::entriesIn;
using test::freshDirectory;
using test::writeFile;

// Runs `body` in a child process and returns how it ended (waitpid's status).
template <class F>
int inChild(F body) {
  const pid_t child = fork();
  if (child == 0) {
    body();
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return status;
}

TEST(InterruptCleanup, CtrlCRemovesOpenTemporariesAndExitsWith130) {
  const auto dir = freshDirectory("interrupt");
  const int status = inChild([&] {
    installInterruptCleanup();
    AtomicFile file(dir / "out.csv");
    file.write(std::string_view("half a file"));
    file.flush();
    AtomicFile done(dir / "done.csv");
    done.write(std::string_view("complete"));
    done.commit();
    raise(SIGINT);
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_EQ(entriesIn(dir), 1u);  // done.csv, committed before the signal
  EXPECT_TRUE(std::filesystem::exists(dir / "done.csv"));
}

TEST(InterruptCleanup, RemovesAFolderOfFramesAndKeepsReleasedPaths) {
  const auto dir = freshDirectory("interrupt-folder");
  const int status = inChild([&] {
    installInterruptCleanup();
    std::filesystem::create_directory(dir / "frames.partial");
    for (int i = 0; i < 300; ++i)
      writeFile(dir / "frames.partial" / ("frame_" + std::to_string(i) + ".png"), "png");
    InterruptCleanup frames(dir / "frames.partial", InterruptCleanup::Kind::folder);
    writeFile(dir / "kept.txt", "kept");
    InterruptCleanup kept(dir / "kept.txt");
    kept.release();
    raise(SIGTERM);
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  EXPECT_FALSE(std::filesystem::exists(dir / "frames.partial"));
  EXPECT_TRUE(std::filesystem::exists(dir / "kept.txt"));
}

TEST(GracefulStop, TheFirstSignalSetsTheFlagTheSecondCleansUp) {
  const auto dir = freshDirectory("interrupt-graceful");
  const int status = inChild([&] {
    installInterruptCleanup();
    std::atomic<bool> stop{false};
    GracefulStop graceful(stop);
    AtomicFile file(dir / "checkpoint.bin");
    raise(SIGINT);
    if (!stop.load()) _exit(10);  // the first signal must only ask to stop
    raise(SIGINT);
    _exit(11);  // not reached
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_EQ(entriesIn(dir), 0u);
}

}  // namespace eco
