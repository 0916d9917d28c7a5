// How much memory the machine can give a process now: a scenario's needs are compared with
// it before large arrays are allocated, so that an oversized terrain gets a clear refusal
// instead of swapping for an hour or dying of std::bad_alloc.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace eco {

// MemAvailable of /proc/meminfo, in bytes; nothing where the system does not say.
std::optional<std::uint64_t> availableMemoryBytes();
// This process's resident memory (VmRSS of /proc/self/status), in bytes; likewise.
std::optional<std::uint64_t> residentMemoryBytes();

// EnvironmentError unless `bytes` fit in the available memory (or `ignore`): the message
// names `what` needs it, both sizes, and ends with `advice` (what to ask for instead, and
// the option that goes ahead anyway).
void requireMemory(std::uint64_t bytes, const std::string& what, const std::string& advice,
                   bool ignore);

// Gives the system back the whole pages in [from, to), which must lie in storage this
// process owns and holds no objects: they read as zeros when next touched. Nothing where
// less than a megabyte would go (not worth the call).
void releasePages(void* from, void* to);

// Gives the system back the pages of an array's storage past its elements, keeping its
// capacity. An array that shrank keeps the pages of its longest length resident otherwise:
// a landscape's plant columns, thinned by a fifth after their peak, would hold a gigabyte
// of rows no longer there. The elements past size() are not objects (trivial ones only), and
// resize() writes the ones it adds.
template <typename T, typename A>
void releaseUnusedCapacity(std::vector<T, A>& array) {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
  releasePages(array.data() + array.size(), array.data() + array.capacity());
}

// "1.2 GB"
std::string formatBytes(std::uint64_t bytes);

}  // namespace eco
