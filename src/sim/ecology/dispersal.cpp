#include "sim/ecology/dispersal.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <tbb/parallel_for.h>

#include "core/angles.hpp"

namespace eco {
namespace {

// Seeds sampled to build a stencil: its shares are good to about a thousandth.
constexpr int kStencilSamples = 400000;
constexpr double kReachInMeans = 5.0;

}  // namespace

glm::dvec2 seedOffsetFrom(const LifeHistory& life, bool longDistance, glm::dvec2 downwind,
                          Rng& rng) {
  const double mean_m = longDistance ? life.longDistanceMean_m : life.dispersalMean_m;
  const double distance = -mean_m * std::log(1.0 - rng.uniform());
  const double angle = 2.0 * kPi * rng.uniform();
  glm::dvec2 offset(distance * std::cos(angle), distance * std::sin(angle));
  if (life.dispersal == DispersalVector::Wind) offset += life.downwindBias * distance * downwind;
  return offset;
}

glm::dvec2 seedOffset(const LifeHistory& life, glm::dvec2 downwind, Rng& rng) {
  const bool far = life.longDistanceFraction > 0.0 && rng.uniform() < life.longDistanceFraction;
  return seedOffsetFrom(life, far, downwind, rng);
}

SeedMap::SeedMap(const Grid& terrain, const std::vector<const LifeHistory*>& species,
                 glm::dvec2 downwind)
    : originEast_m_(-0.5 * terrain.dx_m),
      originNorth_m_(-0.5 * terrain.dy_m),
      width_m_(terrain.width * terrain.dx_m),
      height_m_(terrain.height * terrain.dy_m),
      layersOf_(species.size()) {
  for (int s = 0; s < static_cast<int>(species.size()); ++s) {
    const LifeHistory& life = *species[s];
    for (bool far : {false, true}) {
      const double share = far ? life.longDistanceFraction : 1.0 - life.longDistanceFraction;
      if (share <= 0.0) continue;
      Layer layer;
      layer.species = s;
      layer.share = share;
      const double mean_m = far ? life.longDistanceMean_m : life.dispersalMean_m;
      layer.cell_m = std::clamp(0.8 * mean_m, 10.0, 100.0);
      layer.width = std::max(1, static_cast<int>(std::ceil(width_m_ / layer.cell_m)));
      layer.height = std::max(1, static_cast<int>(std::ceil(height_m_ / layer.cell_m)));
      // The stencil: where a source cell's seeds land, in cells, sampled from the kernel
      // (the source anywhere in its cell), out to five means.
      Rng rng(streamKey(static_cast<std::uint64_t>(s), far ? 1 : 0, purpose("seed stencil")));
      std::map<std::pair<int, int>, int> counts;
      const double reach = kReachInMeans * mean_m * (1.0 + life.downwindBias);
      for (int k = 0; k < kStencilSamples; ++k) {
        const glm::dvec2 start(rng.uniform(), rng.uniform());
        const glm::dvec2 offset = seedOffsetFrom(life, far, downwind, rng);
        if (std::hypot(offset.x, offset.y) > reach) continue;
        const glm::dvec2 land = start + offset / layer.cell_m;
        ++counts[{static_cast<int>(std::floor(land.x)), static_cast<int>(std::floor(land.y))}];
      }
      for (const auto& [cell, count] : counts) {
        layer.stencil.push_back({cell.first, cell.second,
                                 static_cast<float>(static_cast<double>(count) / kStencilSamples)});
        layer.margin = std::max({layer.margin, std::abs(cell.first), std::abs(cell.second)});
      }
      layer.sources.assign(static_cast<std::size_t>(layer.width + 2 * layer.margin) *
                               (layer.height + 2 * layer.margin),
                           0.0);
      layer.density.assign(layer.sources.size(), 0.0f);
      layersOf_[s].push_back(layers_.size());
      layers_.push_back(std::move(layer));
    }
  }
}

glm::ivec2 SeedMap::cellOf(const Layer& layer, double east_m, double north_m) const {
  return {std::clamp(static_cast<int>(std::floor((east_m - originEast_m_) / layer.cell_m)), 0,
                     layer.width - 1),
          std::clamp(static_cast<int>(std::floor((north_m - originNorth_m_) / layer.cell_m)), 0,
                     layer.height - 1)};
}

void SeedMap::clear() {
  for (Layer& layer : layers_) std::fill(layer.sources.begin(), layer.sources.end(), 0.0);
}

void SeedMap::setSurroundingSeeds(int species, double seedsPerM2) {
  for (std::size_t l : layersOf_[species]) {
    Layer& layer = layers_[l];
    const double seeds = seedsPerM2 * layer.cell_m * layer.cell_m * layer.share;
    for (int y = -layer.margin; y < layer.height + layer.margin; ++y)
      for (int x = -layer.margin; x < layer.width + layer.margin; ++x)
        if (x < 0 || y < 0 || x >= layer.width || y >= layer.height)
          layer.sources[sourceOf(layer, x, y)] += seeds;
  }
}

int SeedMap::addSourceRegion(const std::function<bool(glm::dvec2)>& covered) {
  // Each source cell's share under the forest, from 4 x 4 points spread over it.
  constexpr int kSamples = 4;
  for (Layer& layer : layers_) {
    std::vector<Covered>& cells = layer.regions.emplace_back();
    for (int y = -layer.margin; y < layer.height + layer.margin; ++y)
      for (int x = -layer.margin; x < layer.width + layer.margin; ++x) {
        int inside = 0;
        for (int v = 0; v < kSamples; ++v)
          for (int u = 0; u < kSamples; ++u)
            inside += covered({originEast_m_ + (x + (u + 0.5) / kSamples) * layer.cell_m,
                               originNorth_m_ + (y + (v + 0.5) / kSamples) * layer.cell_m});
        if (inside > 0)
          cells.push_back({sourceOf(layer, x, y),
                           static_cast<float>(inside) / static_cast<float>(kSamples * kSamples)});
      }
  }
  return regions_++;
}

bool SeedMap::regionReachesTheMap(int region) const {
  return std::any_of(layers_.begin(), layers_.end(),
                     [&](const Layer& layer) { return !layer.regions[region].empty(); });
}

void SeedMap::addRegionSeeds(int region, int species, double seedsPerM2) {
  for (std::size_t l : layersOf_[species]) {
    Layer& layer = layers_[l];
    const double seeds = seedsPerM2 * layer.cell_m * layer.cell_m * layer.share;
    for (const Covered& c : layer.regions[region]) layer.sources[c.source] += seeds * c.fraction;
  }
}

void SeedMap::addSeeds(int species, double east_m, double north_m, double seeds) {
  for (std::size_t l : layersOf_[species]) {
    Layer& layer = layers_[l];
    const glm::ivec2 cell = cellOf(layer, east_m, north_m);
    layer.sources[sourceOf(layer, cell.x, cell.y)] += seeds * layer.share;
  }
}

void SeedMap::disperse() {
  for (Layer& layer : layers_) {
    // Gathered, not scattered: each target cell sums the sources whose seeds reach it, so
    // rows can run in parallel and the sums do not depend on the thread count.
    const double area = layer.cell_m * layer.cell_m;
    tbb::parallel_for(0, layer.height, [&](int y) {
      for (int x = 0; x < layer.width; ++x) {
        double seeds = 0.0;
        for (const Tap& tap : layer.stencil)
          seeds += layer.sources[sourceOf(layer, x - tap.dx, y - tap.dy)] * tap.share;
        layer.density[static_cast<std::size_t>(y) * layer.width + x] =
            static_cast<float>(seeds / area);
      }
    });
  }
}

double SeedMap::density(int species, double east_m, double north_m) const {
  double seeds = 0.0;
  for (std::size_t l : layersOf_[species]) {
    const Layer& layer = layers_[l];
    const glm::ivec2 cell = cellOf(layer, east_m, north_m);
    seeds += layer.density[static_cast<std::size_t>(cell.y) * layer.width + cell.x];
  }
  return seeds;
}

SeedMap::Lattice SeedMap::latticeOf(const std::vector<double>& easts,
                                    const std::vector<double>& norths) const {
  Lattice lattice;
  for (const Layer& layer : layers_) {
    std::vector<int>& columns = lattice.columns.emplace_back(easts.size());
    std::vector<int>& rows = lattice.rows.emplace_back(norths.size());
    for (std::size_t x = 0; x < easts.size(); ++x) columns[x] = cellOf(layer, easts[x], 0.0).x;
    for (std::size_t y = 0; y < norths.size(); ++y) rows[y] = cellOf(layer, 0.0, norths[y]).y;
  }
  return lattice;
}

double SeedMap::density(int species, const Lattice& lattice, int x, int y) const {
  double seeds = 0.0;
  for (std::size_t l : layersOf_[species]) {
    const Layer& layer = layers_[l];
    seeds += layer.density[static_cast<std::size_t>(lattice.rows[l][y]) * layer.width +
                           lattice.columns[l][x]];
  }
  return seeds;
}

}  // namespace eco
