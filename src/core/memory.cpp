#include "core/memory.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/error.hpp"

namespace eco {

namespace {

// The value of `key` (as "MemAvailable:") in a /proc file of "key: value kB" lines, in bytes.
std::optional<std::uint64_t> procBytes(const char* file, std::string_view key) {
  std::ifstream lines(file);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    std::string name;
    std::uint64_t kilobytes = 0;
    if (fields >> name >> kilobytes && name == key) return kilobytes * 1024;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> availableMemoryBytes() {
  return procBytes("/proc/meminfo", "MemAvailable:");
}

std::optional<std::uint64_t> residentMemoryBytes() {
  return procBytes("/proc/self/status", "VmRSS:");
}

void releasePages(void* from, void* to) {
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(from) + page - 1) / page * page;
  const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(to) / page * page;
  if (end <= first || end - first < (std::uintptr_t{1} << 20)) return;
  // Advice the kernel may not refuse for private memory; were it to, the pages stay.
  madvise(reinterpret_cast<void*>(first), end - first, MADV_DONTNEED);
}

std::string formatBytes(std::uint64_t bytes) {
  std::ostringstream text;
  text.precision(bytes >= 10'000'000'000ull ? 0 : 1);
  text << std::fixed;
  if (bytes >= 1'000'000'000ull)
    text << static_cast<double>(bytes) / 1e9 << " GB";
  else
    text << static_cast<double>(bytes) / 1e6 << " MB";
  return text.str();
}

void requireMemory(std::uint64_t bytes, const std::string& what, const std::string& advice,
                   bool ignore) {
  if (ignore) return;
  const std::optional<std::uint64_t> available = availableMemoryBytes();
  if (!available || bytes <= *available) return;
  throw EnvironmentError(what + " needs about " + formatBytes(bytes) + " of memory; " +
                         formatBytes(*available) + " is available. " + advice);
}

}  // namespace eco
