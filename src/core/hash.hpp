// FNV-1a, a small non-cryptographic 64-bit hash: random-stream purposes, file fingerprints,
// the impostor cache's checksums and those of the first checkpoint and snapshot formats
// (the later ones are XXH3's, sim/run/checksummed_output.hpp).
#pragma once

#include <cstdint>
#include <string_view>

namespace eco {

constexpr std::uint64_t fnv1a64(std::string_view bytes,
                                std::uint64_t hash = 0xcbf29ce484222325ULL) {
  for (char c : bytes) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return hash;
}

}  // namespace eco
