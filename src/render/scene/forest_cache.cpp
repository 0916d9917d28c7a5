#include "render/scene/forest_cache.hpp"

#include <algorithm>

#include "core/memory.hpp"

namespace eco {

ForestCache::ForestCache(Load load, std::uint64_t budgetBytes)
    : load_(std::move(load)), budget_(budgetBytes) {}

std::uint64_t ForestCache::keptBytes() const {
  std::uint64_t bytes = 0;
  for (const auto& [year, forest] : kept_) bytes += forest.memoryBytes();
  return bytes;
}

void ForestCache::makeRoom(std::uint64_t more) {
  while (!kept_.empty() && keptBytes() + more > budget_) kept_.pop_back();
}

const Forest& ForestCache::of(int year) {
  const auto found = std::find_if(kept_.begin(), kept_.end(),
                                  [&](const auto& kept) { return kept.first == year; });
  if (found != kept_.end()) {
    kept_.splice(kept_.begin(), kept_, found);
    return kept_.front().second;
  }
  // Room first for one more as large as the largest kept (the years of a run grow alike),
  // so that the new one is not read while all the others are held.
  std::uint64_t largest = 0;
  for (const auto& [kept, forest] : kept_) largest = std::max(largest, forest.memoryBytes());
  makeRoom(largest);
  Forest loaded = load_(year);
  makeRoom(loaded.memoryBytes());  // then for it as it is: it stays, over the budget if need be
  kept_.emplace_front(year, std::move(loaded));
  return kept_.front().second;
}

std::uint64_t defaultForestCacheBudget() {
  constexpr std::uint64_t kUnknown = std::uint64_t{4} << 30;
  const std::optional<std::uint64_t> available = availableMemoryBytes();
  return available ? *available / 2 : kUnknown;
}

}  // namespace eco
