// The forests of a run's snapshot years as `view` steps through them: each read when first
// shown and kept while the forests kept fit a budget of bytes, the least recently shown
// going first. The valley's fifteen years (230 MB each) all stay; a landscape's years (a
// hundred million plants, 6.7 GB each) are read again rather than held past the memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <utility>

#include "render/scene/forest.hpp"

namespace eco {

class ForestCache {
 public:
  using Load = std::function<Forest(int year)>;
  ForestCache(Load load, std::uint64_t budgetBytes);

  // The forest of `year`, read unless kept; valid until the next call.
  const Forest& of(int year);
  std::size_t keptCount() const { return kept_.size(); }
  std::uint64_t keptBytes() const;

 private:
  // Drops the least recently shown forests until those kept and `more` bytes fit the budget.
  void makeRoom(std::uint64_t more);

  Load load_;
  std::uint64_t budget_;
  std::list<std::pair<int, Forest>> kept_;  // the most recently shown first
};

// The budget `view` gives its cache: half the memory the machine had available as it
// started (4 GB where the system does not say).
std::uint64_t defaultForestCacheBudget();

}  // namespace eco
