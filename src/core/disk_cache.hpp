// A folder of results that are slow to make and cheap to keep (impostor atlases), each under
// a 64-bit key that hashes everything the result depends on, kept between runs of the
// program as a build tool's object cache is. A file is read back as untrusted input: its
// magic, version, key, length and checksum are checked, and a file that fails is removed
// and reads as absent, so a torn or stale file costs a fresh make, never a wrong result.
// Writing is best effort (a full disk or a read-only home warns once and goes on without
// the cache); the least recently used files go when the folder grows past its capacity.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace eco {

// The user's cache folder for ecoforest: ECOFOREST_CACHE_DIR where set ("off" or empty:
// none), else $XDG_CACHE_HOME/ecoforest, else $HOME/.cache/ecoforest; none without a home.
std::optional<std::filesystem::path> userCacheFolder();

// A 64-bit key built from the parts a result depends on, in order (FNV-1a over each).
class CacheKey {
 public:
  CacheKey& add(std::string_view bytes);
  template <typename T>
  CacheKey& addValue(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    return add(std::string_view(reinterpret_cast<const char*>(&value), sizeof value));
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

// A hash of the running program's executable: results made by one build are never read by
// another, whose code may make them differently. Nothing where the executable cannot be read
// (no /proc): then nothing may be cached.
std::optional<std::uint64_t> programIdentity();

class DiskCache {
 public:
  static constexpr std::uintmax_t kDefaultCapacity = std::uintmax_t{2} << 30;  // 2 GiB

  // The folder is made when the first result is written.
  explicit DiskCache(std::filesystem::path folder, std::uintmax_t capacityBytes = kDefaultCapacity);

  // The bytes written under the key, or nothing (never written, evicted, or a file that
  // fails its checks, which is removed). A hit counts as a use for the eviction order.
  std::optional<std::string> read(std::uint64_t key) const;
  // Keeps the bytes under the key, then evicts the least recently used files beyond the
  // capacity. Never throws: a failure warns once on stderr and turns writing off.
  void write(std::uint64_t key, std::string_view bytes);

  const std::filesystem::path& folder() const { return folder_; }
  std::filesystem::path fileOf(std::uint64_t key) const;

 private:
  void evict() const;

  std::filesystem::path folder_;
  std::uintmax_t capacity_;
  bool writable_ = true;
};

}  // namespace eco
