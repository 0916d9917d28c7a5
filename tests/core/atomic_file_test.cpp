#include "core/atomic_file.hpp"

#include <sys/resource.h>
#include <csignal>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_files.hpp"

namespace eco {
using test::entriesIn;
using test::freshDirectory;
using test::readFile;

TEST(AtomicFile, AppearsOnlyOnCommit) {
  auto dir = freshDirectory("atomic");
  {
    AtomicFile file(dir / "a.txt");
    file.write(std::string_view("hello"));
    EXPECT_FALSE(std::filesystem::exists(dir / "a.txt"));
    // The one entry is the temporary, which a run folder's cleanup recognises.
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      EXPECT_TRUE(isAtomicTemporary(entry.path().filename().string())) << entry.path();
    EXPECT_FALSE(isAtomicTemporary("a.txt"));
    file.commit();
  }
  EXPECT_EQ(readFile(dir / "a.txt"), "hello");
  EXPECT_EQ(entriesIn(dir), 1u);  // no temporary left behind
}

TEST(AtomicFile, AbandonedFileLeavesNothing) {
  auto dir = freshDirectory("abandon");
  {
    AtomicFile file(dir / "b.txt");
    file.write(std::string_view("partial"));
  }
  EXPECT_EQ(entriesIn(dir), 0u);
}

TEST(AtomicFile, UnwritableFolderIsAnInputError) {
  EXPECT_THROW(AtomicFile("/nonexistent/folder/x.txt"), InputError);
}

// A file-size limit makes writes fail as a full disk does (EFBIG instead of ENOSPC).
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &saved_);
    previous_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_);
  }

 private:
  rlimit saved_{};
  void (*previous_)(int) = nullptr;
};

TEST(AtomicFile, AFullDiskIsAnEnvironmentErrorAndLeavesNothing) {
  auto dir = freshDirectory("full");
  const std::string megabyte(std::size_t{1} << 20, 'x');
  try {
    FileSizeLimit limit(100000);
    AtomicFile file(dir / "big.bin");
    file.write(megabyte);  // buffered: the failure comes when it reaches the disk
    file.write(megabyte);
    file.commit();
    FAIL() << "a write beyond the limit succeeded";
  } catch (const EnvironmentError& error) {
    EXPECT_NE(std::string(error.what()).find("big.bin: writing failed: File too large"),
              std::string::npos)
        << error.what();
  }
  EXPECT_EQ(entriesIn(dir), 0u);
}

TEST(AtomicFile, CommitChecksTheLastBytes) {
  // Less than the buffer: nothing reaches the disk before commit, which must report it.
  auto dir = freshDirectory("full-last");
  FileSizeLimit limit(1000);
  AtomicFile file(dir / "small.bin");
  file.write(std::string(5000, 'y'));
  EXPECT_THROW(file.commit(), EnvironmentError);
  EXPECT_EQ(entriesIn(dir), 0u);
}

TEST(AtomicFileSet, AllOrNothing) {
  auto dir = freshDirectory("set");
  {
    AtomicFileSet set;
    set.add(dir / "one").write(std::string_view("1"));
    set.add(dir / "two").write(std::string_view("2"));
    // Destroyed without commit, as when an exception unwinds an export.
  }
  EXPECT_EQ(entriesIn(dir), 0u);
  AtomicFileSet set;
  AtomicFile& first = set.add(dir / "one");
  for (int i = 0; i < 20; ++i) set.add(dir / ("more" + std::to_string(i)));
  first.write(std::string_view("still valid"));  // references survive later additions
  set.commit();
  EXPECT_EQ(entriesIn(dir), 21u);
}

namespace {

AtomicFile writtenFile(const std::filesystem::path& target, std::string_view text) {
  AtomicFile file(target);
  file.write(text);
  return file;
}

}  // namespace

TEST(BackgroundCommits, RenamesTheFilesIntoPlaceInTheirOrder) {
  auto dir = freshDirectory("background");
  BackgroundCommits commits;
  commits.commit(writtenFile(dir / "a.txt", "first"));
  commits.commit(writtenFile(dir / "b.txt", "other"));
  commits.commit(writtenFile(dir / "a.txt", "second"));  // renamed after the first
  commits.wait();
  EXPECT_EQ(readFile(dir / "a.txt"), "second");
  EXPECT_EQ(readFile(dir / "b.txt"), "other");
  EXPECT_EQ(entriesIn(dir), 2u);  // no temporary left behind
}

TEST(BackgroundCommits, ItsEndWaitsForTheFiles) {
  auto dir = freshDirectory("background-end");
  {
    BackgroundCommits commits;
    commits.commit(writtenFile(dir / "c.txt", "kept"));
  }
  EXPECT_EQ(readFile(dir / "c.txt"), "kept");
  EXPECT_EQ(entriesIn(dir), 1u);
}

TEST(BackgroundCommits, AFailureIsRethrownAndStopsTheFilesAfterIt) {
  auto dir = freshDirectory("background-full");
  BackgroundCommits commits;
  {
    // Below the buffer: the bytes reach the disk in the commit, on the other thread.
    FileSizeLimit limit(1000);
    try {
      commits.commit(writtenFile(dir / "big.bin", std::string(5000, 'y')));
      // Where the first has failed by now, this commit rethrows its failure, else wait() does.
      commits.commit(writtenFile(dir / "after.txt", "small"));
      commits.wait();
      FAIL() << "a commit beyond the file size limit succeeded";
    } catch (const EnvironmentError& error) {
      EXPECT_NE(std::string(error.what()).find("big.bin: writing failed"), std::string::npos)
          << error.what();
    }
  }
  EXPECT_EQ(entriesIn(dir), 0u);  // neither file, nor a temporary
  // The failure was reported: later files are committed again.
  commits.commit(writtenFile(dir / "later.txt", "fine"));
  commits.wait();
  EXPECT_EQ(readFile(dir / "later.txt"), "fine");
}

}  // namespace eco
