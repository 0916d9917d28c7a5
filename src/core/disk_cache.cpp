#include "core/disk_cache.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <system_error>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/binary_io.hpp"
#include "core/hash.hpp"
#include "core/mapped_file.hpp"

namespace eco {
namespace {

constexpr std::string_view kMagic = "ecoforest cache\n";
constexpr std::uint32_t kVersion = 1;
constexpr std::string_view kExtension = ".cache";
// magic, version, key, length, then the bytes and the checksum of all before it.
constexpr std::size_t kHeaderBytes =
    kMagic.size() + sizeof(std::uint32_t) + 2 * sizeof(std::uint64_t);

}  // namespace

std::optional<std::filesystem::path> userCacheFolder() {
  if (const char* chosen = std::getenv("ECOFOREST_CACHE_DIR")) {
    const std::string_view folder(chosen);
    if (folder.empty() || folder == "off") return std::nullopt;
    return std::filesystem::path(folder);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && xdg[0] == '/')
    return std::filesystem::path(xdg) / "ecoforest";
  if (const char* home = std::getenv("HOME"); home && home[0] != '\0')
    return std::filesystem::path(home) / ".cache" / "ecoforest";
  return std::nullopt;
}

CacheKey& CacheKey::add(std::string_view bytes) {
  // The length first, so that parts cannot run into each other ("ab" + "c" is not "a" + "bc").
  const std::uint64_t length = bytes.size();
  hash_ = fnv1a64(std::string_view(reinterpret_cast<const char*>(&length), sizeof length), hash_);
  hash_ = fnv1a64(bytes, hash_);
  return *this;
}

std::optional<std::uint64_t> programIdentity() {
  static const std::optional<std::uint64_t> identity = []() -> std::optional<std::uint64_t> {
    const std::optional<MappedFile> program = MappedFile::open("/proc/self/exe");
    if (!program) return std::nullopt;
    return fnv1a64(program->bytes());
  }();
  return identity;
}

DiskCache::DiskCache(std::filesystem::path folder, std::uintmax_t capacityBytes)
    : folder_(std::move(folder)), capacity_(capacityBytes) {}

std::filesystem::path DiskCache::fileOf(std::uint64_t key) const {
  char name[17];
  std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(key));
  return folder_ / (std::string(name) + std::string(kExtension));
}

std::optional<std::string> DiskCache::read(std::uint64_t key) const {
  const std::filesystem::path file = fileOf(key);
  // Mapped, not read through a stream: an atlas is megabytes.
  const std::optional<MappedFile> mapped = MappedFile::open(file);
  if (!mapped) return std::nullopt;
  const std::string_view all = mapped->bytes();
  BinaryReader header(all);
  std::string magic(kMagic.size(), '\0');
  for (char& c : magic) c = header.get<char>();
  const auto version = header.get<std::uint32_t>();
  const auto storedKey = header.get<std::uint64_t>();
  const auto length = header.get<std::uint64_t>();
  std::error_code ignored;
  const bool whole = !header.failed() && all.size() >= kHeaderBytes + sizeof(std::uint64_t) &&
                     magic == kMagic && version == kVersion && storedKey == key &&
                     length == all.size() - kHeaderBytes - sizeof(std::uint64_t);
  std::uint64_t checksum = 0;
  if (whole) std::memcpy(&checksum, all.data() + all.size() - sizeof checksum, sizeof checksum);
  if (!whole || checksum != fnv1a64(all.substr(0, all.size() - sizeof checksum))) {
    std::filesystem::remove(file, ignored);  // torn, stale or not ours: made afresh
    return std::nullopt;
  }
  // A use: the eviction keeps the recently used.
  std::filesystem::last_write_time(file, std::filesystem::file_time_type::clock::now(), ignored);
  return std::string(all.substr(kHeaderBytes, length));
}

void DiskCache::write(std::uint64_t key, std::string_view bytes) {
  if (!writable_) return;
  try {
    std::filesystem::create_directories(folder_);
    BinaryWriter header;
    for (const char c : kMagic) header.put(c);
    header.put(kVersion);
    header.put(key);
    header.put<std::uint64_t>(bytes.size());
    const std::uint64_t checksum = fnv1a64(bytes, fnv1a64(header.bytes()));
    AtomicFile out(fileOf(key));
    out.write(header.bytes());
    out.write(bytes);
    out.write(std::string_view(reinterpret_cast<const char*>(&checksum), sizeof checksum));
    out.commit();
    evict();
  } catch (const std::exception& error) {
    writable_ = false;
    std::cerr << "ecoforest: warning: cannot keep results in the cache folder " << folder_.string()
              << " (" << error.what() << "); they are made afresh each time "
              << "(ECOFOREST_CACHE_DIR=off turns the cache off)\n";
  }
}

void DiskCache::evict() const {
  struct Entry {
    std::filesystem::file_time_type used;
    std::uintmax_t bytes;
    std::filesystem::path file;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder_, error)) {
    std::error_code skip;
    if (entry.path().extension() != kExtension || !entry.is_regular_file(skip)) continue;
    const std::uintmax_t bytes = entry.file_size(skip);
    const auto used = entry.last_write_time(skip);
    if (skip) continue;  // gone meanwhile (another process evicting)
    entries.push_back({used, bytes, entry.path()});
    total += bytes;
  }
  if (total <= capacity_) return;
  // Oldest use first; ties by name, so that two processes evict alike.
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.used != b.used ? a.used < b.used : a.file < b.file;
  });
  for (const Entry& entry : entries) {
    if (total <= capacity_) break;
    std::filesystem::remove(entry.file, error);
    total -= entry.bytes;
  }
}

}  // namespace eco
