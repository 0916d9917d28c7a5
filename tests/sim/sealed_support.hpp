// A sealed file (sim/run/checksummed_output.hpp) as an older version wrote it: the readers
// of checkpoints and binary snapshots go on reading the versions before XXH3.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "sim/run/checksummed_output.hpp"

namespace eco::test {

// `bytes` of a file of `magic` with its version set to `version` and sealed again by `hash`.
inline std::string resealed(std::string bytes, std::string_view magic, std::uint32_t version,
                            BlockHash hash) {
  const std::size_t versionAt = sealedHeader(magic, 0).bytes().size() - sizeof version;
  std::memcpy(bytes.data() + versionAt, &version, sizeof version);
  bytes.resize(bytes.size() - sizeof(std::uint64_t));
  const std::uint64_t checksum = blockChecksum(bytes, hash);
  return bytes + std::string(reinterpret_cast<const char*>(&checksum), sizeof checksum);
}

}  // namespace eco::test
