// Where seeds land (docs/ecology.md, "Reproduction").
// A seed travels an exponentially distributed distance in a uniformly random direction, with
// the species' mean; a two-part kernel sends a share of the seeds with a longer mean instead
// (TreeMig, Lischke et al. 2006, as iLand parameterises it), and wind-dispersed seeds drift
// downwind by downwind_bias metres per metre travelled.
// A year's seeds are not followed one by one (a mast year of beech sends millions per
// hectare): each species' mature crowns put their seeds onto a grid of sources, and the
// kernel, sampled once into a stencil, spreads them into a density of seeds per m2 over the
// map. The kernel's short part lies on a grid of 0.8 times its mean (10 .. 100 m), the long
// part on its own coarser grid, each out to five means.
#pragma once

#include <functional>
#include <vector>

#include <glm/vec2.hpp>

#include "core/random.hpp"
#include "sim/ecology/species_ecology.hpp"
#include "sim/grid.hpp"

namespace eco {

// The map offset (east, north) of one seed from its parent, from the kernel's short part or
// its long part. `downwind` is the unit vector toward which the prevailing wind blows.
glm::dvec2 seedOffsetFrom(const LifeHistory& life, bool longDistance, glm::dvec2 downwind,
                          Rng& rng);
// One seed of the whole kernel (the long part with the species' long-distance share).
glm::dvec2 seedOffset(const LifeHistory& life, glm::dvec2 downwind, Rng& rng);

// Seed density over the map, species by species, for one year.
class SeedMap {
 public:
  SeedMap(const Grid& terrain, const std::vector<const LifeHistory*>& species, glm::dvec2 downwind);

  // Starts a year: no seeds.
  void clear();
  void addSeeds(int species, double east_m, double north_m, double seeds);
  // The forest around the map sends this year this many seeds of a species per m2 of its
  // ground: its seeds reach into the map by the same kernel as the map's own.
  void setSurroundingSeeds(int species, double seedsPerM2);
  // A forest of its own ground (a [[seed_source]], on or off the map): `covered` is sampled
  // once over every seed grid out to the kernels' reach beyond the map. Returns its number.
  int addSourceRegion(const std::function<bool(glm::dvec2)>& covered);
  // Whether any of the region's ground lies within the kernels' reach of the map.
  bool regionReachesTheMap(int region) const;
  // This year the region's forest sends this many seeds of a species per m2 of its ground.
  void addRegionSeeds(int region, int species, double seedsPerM2);
  // Spreads the sources by each species' kernel.
  void disperse();
  // Seeds per m2 of a species at a map position this year (before any seed rain).
  double density(int species, double east_m, double north_m) const;

  // The seed cells of every layer under a lattice of places, the east of each column and the
  // north of each row: a lattice's places share their columns and rows, so a pass over
  // millions of them (establishment's regeneration cells) finds each once, not a division
  // per layer per place. density(species, lattice, x, y) is density(species, easts[x],
  // norths[y]), to the bit.
  struct Lattice {
    std::vector<std::vector<int>> columns, rows;  // per layer
  };
  Lattice latticeOf(const std::vector<double>& easts, const std::vector<double>& norths) const;
  double density(int species, const Lattice& lattice, int x, int y) const;

 private:
  struct Tap {
    int dx, dy;
    float share;  // of a source's seeds
  };
  struct Covered {
    std::size_t source;  // index into the layer's sources
    float fraction;      // of the source cell's area under the forest
  };
  struct Layer {  // one kernel part of one species on its own grid
    int species = 0;
    double share = 1.0;  // of the species' seeds that take this part
    double cell_m = 20.0;
    int width = 0, height = 0;  // the cells over the map
    // Sources lie on the map's cells and a margin of cells around it as wide as the
    // stencil reaches: seeds from farther away cannot land on the map.
    int margin = 0;
    std::vector<Tap> stencil;
    std::vector<double> sources;  // seeds per cell, (width + 2 margin) x (height + 2 margin)
    std::vector<float> density;   // seeds per m2, width x height
    std::vector<std::vector<Covered>> regions;  // per source region, the cells it covers
  };
  // The layer's cell (x east, y north) holding a map position, clamped to the map's cells.
  glm::ivec2 cellOf(const Layer& layer, double east_m, double north_m) const;
  std::size_t sourceOf(const Layer& layer, int x, int y) const {
    return static_cast<std::size_t>(y + layer.margin) * (layer.width + 2 * layer.margin) +
           static_cast<std::size_t>(x + layer.margin);
  }

  double originEast_m_, originNorth_m_, width_m_, height_m_;
  int regions_ = 0;
  std::vector<Layer> layers_;
  std::vector<std::vector<std::size_t>> layersOf_;  // per species, its layers' indices
};

}  // namespace eco
