#include "render/scene/forest_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <tbb/parallel_for.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/error.hpp"

namespace eco {
namespace {

// Height bands a fourth of an octave wide from 1/8 m to 128 m, with one below and one above,
// numbered from the tallest down (a tile's groups in that order).
constexpr int kBandsPerOctave = 4;
constexpr float kLowestBand_m = 0.125f;
constexpr int kBands = 10 * kBandsPerOctave + 2;

int bandFromTheTop(float height_m) {
  if (!(height_m >= kLowestBand_m)) return kBands - 1;
  const int above =
      static_cast<int>(std::floor(kBandsPerOctave * std::log2(height_m / kLowestBand_m)));
  return kBands - 2 - std::min(above, kBands - 2);
}

}  // namespace

ForestIndex::ForestIndex(const Forest& forest, const TreeLibrary& library) {
  const std::size_t n = forest.size();
  ECO_ASSERT(n < std::numeric_limits<std::uint32_t>::max(), "more trees than 32-bit indices");
  if (n == 0) return;
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const glm::vec3& p : forest.position) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const auto columns = static_cast<std::size_t>((hi.x - lo.x) / kTile_m) + 1;
  const auto rows = static_cast<std::size_t>((hi.z - lo.z) / kTile_m) + 1;
  ECO_ASSERT(columns * rows * kBands < std::numeric_limits<std::uint32_t>::max(),
             "more tiles than 32-bit keys");
  // A tree's drawn height, as ForestRenderer::prepare counts it, and its reach: its drawn
  // sphere is centred within its type's bounds' offset from the stem and both scale by at
  // most the larger of its scales, so the sphere lies within that offset and its radius of
  // the stem.
  auto heightOf = [&](std::size_t i) {
    return library.type(forest.type[i]).height_m * forest.scaleY[i];
  };
  auto reachOf = [&](std::size_t i) {
    const TreeType& type = library.type(forest.type[i]);
    return (glm::length(glm::vec3(type.bounds)) + type.bounds.w) *
           std::max(forest.scaleXZ[i], forest.scaleY[i]);
  };
  // Each tree's group: its tile, then its band.
  std::vector<std::uint32_t> group(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    const glm::vec3 p = forest.position[i];
    const auto cx = static_cast<std::size_t>((p.x - lo.x) / kTile_m);
    const auto cz = static_cast<std::size_t>((p.z - lo.z) / kTile_m);
    group[i] =
        static_cast<std::uint32_t>((cz * columns + cx) * kBands + bandFromTheTop(heightOf(i)));
  });
  // Counting sort by group, trees in forest order within each.
  std::vector<std::uint32_t> start(columns * rows * kBands + 1, 0);
  for (const std::uint32_t g : group) ++start[g + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  trees_.resize(n);
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) trees_[next[group[i]]++] = static_cast<std::uint32_t>(i);
  }
  // The groups and tiles that hold trees.
  for (std::size_t t = 0; t < columns * rows; ++t) {
    Tile tile;
    tile.firstGroup = static_cast<std::uint32_t>(groups_.size());
    for (std::size_t g = t * kBands; g < (t + 1) * kBands; ++g)
      if (start[g] != start[g + 1]) groups_.push_back({start[g], start[g + 1], 0.0f});
    tile.lastGroup = static_cast<std::uint32_t>(groups_.size());
    if (tile.firstGroup != tile.lastGroup) tiles_.push_back(tile);
  }
  tbb::parallel_for(std::size_t{0}, tiles_.size(), [&](std::size_t t) {
    Tile& tile = tiles_[t];
    glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
    float farthest = 0.0f;
    for (std::uint32_t g = tile.firstGroup; g < tile.lastGroup; ++g)
      for (std::uint32_t k = groups_[g].first; k < groups_[g].last; ++k) {
        const std::uint32_t i = trees_[k];
        groups_[g].tallest = std::max(groups_[g].tallest, heightOf(i));
        low = glm::min(low, forest.position[i]), high = glm::max(high, forest.position[i]);
        farthest = std::max(farthest, reachOf(i));
      }
    // Room for the roundings of each tree's own sums (a centre 10 km out is rounded to a
    // millimetre).
    constexpr float kSlack_m = 0.05f;
    tile.lo = low - (farthest + kSlack_m);
    tile.hi = high + (farthest + kSlack_m);
  });
}

}  // namespace eco
