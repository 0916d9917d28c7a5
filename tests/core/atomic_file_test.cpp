#include "core/atomic_file.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_files.hpp"

namespace eco {
using test::entriesIn;
using test::freshDirectory;

TEST(AtomicFile, AppearsOnlyOnCommit) {
  auto dir = freshDirectory("atomic");
  {
    AtomicFile file(dir / "a.txt");
    file.write(std::string_view("hello"));
    EXPECT_FALSE(std::filesystem::exists(dir / "a.txt"));
    file.commit();
  }
  std::ifstream in(dir / "a.txt");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "hello");
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

}  // namespace eco
