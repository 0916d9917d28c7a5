#include "core/disk_cache.hpp"

#include <chrono>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "test_files.hpp"

namespace eco {
namespace {

std::string bytesOf(std::size_t size, int seed) {
  std::string bytes(size, '\0');
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<char>(i * 31 + seed);
  return bytes;
}

TEST(DiskCache, GivesBackWhatWasWrittenUnderItsKeyAndNothingUnderAnother) {
  const auto folder = test::freshDirectory("disk_cache") / "not yet made";
  DiskCache cache(folder);
  EXPECT_FALSE(cache.read(7).has_value());
  const std::string bytes = bytesOf(100'000, 1);
  cache.write(7, bytes);
  EXPECT_EQ(cache.read(7), bytes);
  EXPECT_FALSE(cache.read(8).has_value());
  // Another cache on the same folder (the next run of the program) reads it too.
  EXPECT_EQ(DiskCache(folder).read(7), bytes);
  cache.write(7, "");  // replaced, and empty is a value
  EXPECT_EQ(cache.read(7), "");
}

// A file of the cache is untrusted: torn, edited or renamed, it reads as absent and is
// removed, so the result is made afresh.
TEST(DiskCache, AFileThatFailsItsChecksReadsAsAbsentAndIsRemoved) {
  const auto folder = test::freshDirectory("disk_cache_faults");
  DiskCache cache(folder);
  const std::string bytes = bytesOf(5000, 2);
  auto damaged = [&](auto&& damage) {
    cache.write(1, bytes);
    std::string file = test::readFile(cache.fileOf(1));
    damage(file);
    test::writeFile(cache.fileOf(1), file);
    const bool absent = !cache.read(1).has_value();
    return absent && !std::filesystem::exists(cache.fileOf(1));
  };
  EXPECT_TRUE(damaged([](std::string& f) { f[f.size() / 2] ^= 1; })) << "a flipped bit";
  EXPECT_TRUE(damaged([](std::string& f) { f.resize(f.size() - 100); })) << "torn";
  EXPECT_TRUE(damaged([](std::string& f) { f.resize(10); })) << "shorter than its header";
  EXPECT_TRUE(damaged([](std::string& f) { f.clear(); })) << "empty";
  EXPECT_TRUE(damaged([](std::string& f) { f[0] = 'x'; })) << "not ours";
  // Another key's file renamed to this key's name: its key does not match.
  cache.write(2, bytes);
  std::filesystem::rename(cache.fileOf(2), cache.fileOf(1));
  EXPECT_FALSE(cache.read(1).has_value());
  // And the intact file still reads.
  cache.write(1, bytes);
  EXPECT_EQ(cache.read(1), bytes);
}

TEST(DiskCache, EvictsTheLeastRecentlyUsedBeyondItsCapacity) {
  const auto folder = test::freshDirectory("disk_cache_evict");
  // Room for two files of 1000 bytes and their headers, not three.
  DiskCache cache(folder, 2500);
  const auto old = std::filesystem::file_time_type::clock::now() - std::chrono::hours(2);
  cache.write(1, bytesOf(1000, 1));
  cache.write(2, bytesOf(1000, 2));
  std::filesystem::last_write_time(cache.fileOf(1), old - std::chrono::hours(1));
  std::filesystem::last_write_time(cache.fileOf(2), old);
  ASSERT_TRUE(cache.read(1).has_value());  // a use: 1 is now the most recent
  test::writeFile(folder / "notes.txt", std::string(10'000, 'n'));  // not the cache's: kept
  cache.write(3, bytesOf(1000, 3));
  EXPECT_TRUE(cache.read(1).has_value());
  EXPECT_FALSE(cache.read(2).has_value()) << "the least recently used";
  EXPECT_TRUE(cache.read(3).has_value());
  EXPECT_TRUE(std::filesystem::exists(folder / "notes.txt"));
}

TEST(DiskCache, AFolderThatCannotBeWrittenTurnsWritingOffWithoutFailing) {
  const auto folder = test::freshDirectory("disk_cache_blocked");
  test::writeFile(folder / "a file", "in the way");
  DiskCache cache(folder / "a file" / "cache");
  testing::internal::CaptureStderr();
  cache.write(1, "bytes");
  cache.write(2, "bytes");
  const std::string warned = testing::internal::GetCapturedStderr();
  EXPECT_FALSE(cache.read(1).has_value());
  const std::size_t first = warned.find("cannot keep results in the cache folder");
  ASSERT_NE(first, std::string::npos) << warned;
  EXPECT_EQ(warned.find("cannot keep", first + 1), std::string::npos) << "warned once: " << warned;
}

TEST(DiskCache, KeysTellTheirPartsApartInOrder) {
  EXPECT_EQ(CacheKey().add("ab").add("c").value(), CacheKey().add("ab").add("c").value());
  EXPECT_NE(CacheKey().add("ab").add("c").value(), CacheKey().add("a").add("bc").value());
  EXPECT_NE(CacheKey().add("a").add("b").value(), CacheKey().add("b").add("a").value());
  EXPECT_NE(CacheKey().addValue(1).value(), CacheKey().addValue(2).value());
  ASSERT_TRUE(programIdentity().has_value());
  EXPECT_EQ(programIdentity(), programIdentity());
}

TEST(DiskCache, TheUserFolderFollowsTheEnvironment) {
  // The variables as they were, put back at the end.
  struct Saved {
    const char* name;
    std::optional<std::string> value;
  };
  std::vector<Saved> saved;
  for (const char* name : {"ECOFOREST_CACHE_DIR", "XDG_CACHE_HOME", "HOME"}) {
    const char* value = std::getenv(name);
    saved.push_back({name, value ? std::optional<std::string>(value) : std::nullopt});
  }
  setenv("ECOFOREST_CACHE_DIR", "/some/where", 1);
  EXPECT_EQ(userCacheFolder(), std::filesystem::path("/some/where"));
  setenv("ECOFOREST_CACHE_DIR", "off", 1);
  EXPECT_FALSE(userCacheFolder().has_value());
  unsetenv("ECOFOREST_CACHE_DIR");
  setenv("XDG_CACHE_HOME", "/xdg", 1);
  EXPECT_EQ(userCacheFolder(), std::filesystem::path("/xdg/ecoforest"));
  unsetenv("XDG_CACHE_HOME");
  setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(userCacheFolder(), std::filesystem::path("/home/someone/.cache/ecoforest"));
  unsetenv("HOME");
  EXPECT_FALSE(userCacheFolder().has_value());
  for (const Saved& s : saved)
    if (s.value)
      setenv(s.name, s.value->c_str(), 1);
    else
      unsetenv(s.name);
}

}  // namespace
}  // namespace eco
