// Deterministic, counter-based random numbers (DESIGN.md, "Determinism").
// A stream is keyed by (seed, ids..., purpose); the n-th number of a stream depends only on
// its key and n, never on which thread asks or in what order, so results do not depend on
// the thread count.
#pragma once

#include <cstdint>
#include <string_view>

#include "core/hash.hpp"

namespace eco {

// SplitMix64's finaliser: a bijective 64-bit mix with good avalanche.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A compile-time tag for what the numbers are for (FNV-1a of the name), so that two
// purposes keyed by the same ids draw independent streams.
constexpr std::uint64_t purpose(std::string_view name) {
  return fnv1a64(name);
}

// Combine any number of ids into one stream key.
constexpr std::uint64_t streamKey(std::uint64_t first) {
  return mix64(first);
}
template <typename... Rest>
constexpr std::uint64_t streamKey(std::uint64_t first, std::uint64_t second, Rest... rest) {
  return streamKey(mix64(first) ^ (second + 0x632be59bd9b4e019ULL),
                   static_cast<std::uint64_t>(rest)...);
}

class Rng {
 public:
  explicit Rng(std::uint64_t key) : key_(key) {}

  std::uint64_t nextBits() { return mix64(key_ ^ mix64(counter_++)); }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(nextBits() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Standard normal deviate (Box-Muller; uses two numbers of the stream).
  double normal();
  // Rounds x down or up so that the expected value is x (for fractional counts).
  int stochasticRound(double x);

 private:
  std::uint64_t key_;
  std::uint64_t counter_ = 0;
};

}  // namespace eco
