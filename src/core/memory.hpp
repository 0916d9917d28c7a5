// How much memory the machine can give a process now: a scenario's needs are compared with
// it before large arrays are allocated, so that an oversized terrain gets a clear refusal
// instead of swapping for an hour or dying of std::bad_alloc.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace eco {

// MemAvailable of /proc/meminfo, in bytes; nothing where the system does not say.
std::optional<std::uint64_t> availableMemoryBytes();

// EnvironmentError unless `bytes` fit in the available memory (or `ignore`): the message
// names `what` needs it, both sizes, and `option` to go ahead anyway.
void requireMemory(std::uint64_t bytes, const std::string& what, const std::string& option,
                   bool ignore);

// "1.2 GB"
std::string formatBytes(std::uint64_t bytes);

}  // namespace eco
