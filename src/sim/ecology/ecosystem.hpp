// The afforestation simulation (docs/ecology.md): plants on a terrain, stepped a year at a
// time through light, growth, mortality, seed production and establishment.
// - Light: crowns fill 5 m columns from the top (light_grid.hpp).
// - Growth: saplings in height, trees by the wood their absorbed light leaves after the
//   upkeep of leaves and fine roots (growth.hpp); a crown's lowest branches die where its
//   light falls below the leaf compensation light.
// - Mortality: intrinsic, carbon starvation for trees, poor years for saplings.
// - Reproduction: seed density maps from the mature crowns (dispersal.hpp), the forest
//   around the map and seed rain; a 2 m regeneration cell takes seedlings of the species it
//   does not yet hold until one of its young plants passes 1.3 m, and the first to pass 4 m
//   clears the others, so regeneration is limited by space, seed, site and light, not by
//   the terrain's cell size.
// Every random number is keyed by (scenario seed, year, plant or cell id, purpose), and every
// pass keeps the plants' order, so a run gives the same plants whatever the thread count.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>

#include "core/buffer.hpp"
#include "model/species.hpp"
#include "sim/conditions/conditions.hpp"
#include "sim/ecology/dispersal.hpp"
#include "sim/ecology/growth.hpp"
#include "sim/ecology/light_grid.hpp"
#include "sim/ecology/plant_site.hpp"
#include "sim/ecology/plants.hpp"
#include "sim/ecology/species_ecology.hpp"
#include "sim/scenario.hpp"

namespace eco {

// iLand's sapling layer (Seidl et al. 2012; its saplings.h and saplings.cpp): the map is cut
// into 2 m regeneration cells, each holding young plants (below kRegenerationHeight_m) of
// at most kYoungPlantsPerCell species, one of each. A cell takes seedlings of the species it
// lacks while all its young plants are below breast height (1.3 m); the first to pass
// kRegenerationHeight_m becomes a tree and the cell's other seedlings and saplings die
// (planted stock, which iLand plants as trees, stays). So species that arrive together race
// for the cell by their height growth. The layer's young plants grow as iLand's saplings do,
// in height by the light the trees leave on the ground, and cast no shade: only trees (from
// kRegenerationHeight_m) are crowns in the light grid.
inline constexpr double kRegenerationCell_m = 2.0;
inline constexpr double kRegenerationHeight_m = 4.0;
inline constexpr int kYoungPlantsPerCell = 5;  // iLand's NSAPCELLS

struct EcosystemSpecies {
  Species species;  // its tree model
  Ecology ecology;  // its niche and life history: the file's [ecology]
  double seedRainPerHaPerYear = 0.0;
  // The species' share of the canopy of the forest around the map (its seed source), 0..1.
  double surroundingForestShare = 0.0;
  Field suitability;  // site suitability per cell (altitude, slope, moisture, windiness)
};

// A species file with its [ecology] table (an InputError at `where` when it has none), for
// the caller to add seed rain and suitability.
EcosystemSpecies readEcosystemSpecies(const std::filesystem::path& file,
                                      const SourceLocation& where);

struct EcosystemSettings {
  std::uint64_t seed = Scenario{}.seed;
  double windFrom_deg = Climate{}.prevailingWindFrom_deg;
};

// The state a checkpoint must hold to continue a run exactly.
struct EcosystemState {
  int year = 0;
  std::uint64_t nextId = 1;
  Plants plants;
};

class Ecosystem {
 public:
  // The terrain must outlive the ecosystem; each species brings its site suitability. The
  // fields give the light the terrain lets through to each cell.
  Ecosystem(const Terrain& terrain, const ConditionFields& fields,
            std::vector<EcosystemSpecies> species, const EcosystemSettings& settings);

  // Advances one year; afterwards year() is one higher and bornLastYear()/diedLastYear()
  // hold that year's counts per species.
  void step();

  // Adds a plant of `age` years grown alone at full light on a fully suitable site (sources
  // for tests, grown trees).
  void plant(int species, double east_m, double north_m, int age_years);
  // Adds planted stock: a sapling of this height (below kRegenerationHeight_m) and age. Stock
  // planted where a condition rules its species out and checked for survival
  // (PlantedRuledOut) dies in its first year.
  void plantSapling(int species, double east_m, double north_m, double height_m, int age_years = 0,
                    PlantOrigin origin = PlantOrigin::Planted);
  // Removes the plants whose flag is set (thinning), keeping the others' order.
  void removePlants(const std::vector<std::uint8_t>& removed);

  // Areas kept open: nothing establishes where `isOpen` holds (a [[exclusion]]). Call once,
  // before the first year.
  void keepOpen(std::function<bool(glm::dvec2)> isOpen);
  // A forest on or around the map that sends seeds like the map's own trees: `covered`
  // says which map positions lie under it (it is sampled over the seed grids once), `cover`
  // is the share of its ground under crowns and `shares` each species' share of them.
  // False (and nothing added) when it lies beyond the reach of every kernel.
  bool addSeedSource(const std::function<bool(glm::dvec2)>& covered, double cover,
                     std::vector<double> shares);

  int year() const { return state_.year; }
  const Plants& plants() const { return state_.plants; }
  const std::vector<EcosystemSpecies>& species() const { return species_; }
  const std::vector<int>& bornLastYear() const { return born_; }
  const std::vector<int>& diedLastYear() const { return died_; }
  // Of those that died, the ones that had been planted.
  const std::vector<int>& plantedDiedLastYear() const { return plantedDied_; }
  // Whether a map position lies in an area kept open.
  bool isKeptOpen(glm::dvec2 p) const { return isOpen_ && isOpen_(p); }
  const Grid& grid() const { return terrain_.grid; }
  const Terrain& terrain() const { return terrain_; }
  // The light (fraction of open level ground's) at a height above the ground, under this
  // year's canopy.
  double lightAt(double east_m, double north_m, double height_m) const;
  // The light and wind that shape the form of each of these plants (plant_site.hpp), under
  // this year's canopy, for plants of this ecosystem's map (its own, or the trees a thinning
  // removed this year); before the first step (no canopy yet) all neutral.
  std::vector<PlantSite> sitesOf(const Plants& plants) const;
  PlantSite siteOf(const Plants& plants, std::size_t i) const;
  // What a plant's position and id give (plants.hpp), for plants of this ecosystem's map:
  // the terrain grid's cell holding the stem, the ground's altitude there, and the tree
  // model's individual seed (32 bits, which spreadsheets, R and JavaScript hold exactly:
  // their numbers are doubles).
  std::size_t cellOf(const Plants& plants, std::size_t i) const;
  float groundOf(const Plants& plants, std::size_t i) const;
  std::uint32_t variantSeedOf(std::uint64_t id) const;

  const EcosystemState& state() const { return state_; }
  void restore(EcosystemState state);

 private:
  // The plants' crowns as the light grid reads them: their own columns, this year's trees'
  // rows and leaf areas.
  CrownColumns crownsOf(const Plants& p) const;
  // This year's trees: the rows of the plants of kRegenerationHeight_m and more.
  void findTrees();
  void computeLight();
  void grow();
  void applyMortality();
  // Frees the year's arrays per tree and the light grid's crown entries once mortality has
  // read them: establishment and settling, where the year's seedlings join the plants, do
  // not need them (docs/performance.md, "the year's arrays while seedlings come").
  void releaseTreeArrays();
  void produceSeeds();
  void establish();
  // The plants are kept in order of place: of their light column (5 m, rows from the south,
  // each from the west), and of birth within a column. Neighbours then lie near each other
  // in memory, and so do the light columns, crowns and seed cells each year's passes read
  // for them: in birth order each plant's came from anywhere on the map, and the valley's
  // run took an eighth longer, waiting for memory (docs/performance.md, "Plants in order of
  // place"). The plants appended since the last call, established or planted, are moved
  // into that order.
  void settleNewcomers();
  // Makes row i a sapling of this height (below kRegenerationHeight_m), shaped as the sapling
  // layer shapes it: from breast height on, the diameter of the sapling height/diameter ratio
  // and its crown; below it, no diameter.
  void setSaplingHeight(std::size_t i, double height_m);
  // Appends a seedling of the species at a place; returns its row.
  std::size_t addPlant(int species, double east_m, double north_m);
  // Makes row i a seedling with this id (the rows of a year's seedlings are made side by
  // side).
  void setSeedling(std::size_t i, std::uint64_t id, int species, double east_m, double north_m);
  // The regeneration cells: 2 m squares from the terrain grid's south-west corner.
  glm::dvec2 regenerationOrigin() const;
  // The cell of a map position (clamped to the map), and a cell's centre.
  std::size_t regenerationCellOf(double east_m, double north_m) const;
  glm::dvec2 regenerationCentre(int x, int y) const;

  const Terrain& terrain_;
  std::vector<EcosystemSpecies> species_;
  std::vector<double> seedlingCrownLimit_m_;  // per species: seedlingCrownRadiusLimit
  std::vector<FoliageLimit> foliageLimit_;    // per species: foliageLimitOf
  EcosystemSettings settings_;
  glm::dvec2 downwind_;  // the prevailing wind's direction (mapDownwindOf)
  LightGrid light_;
  bool lightComputed_ = false;  // the light grid holds a year's canopy
  Field windiness_;             // the conditions', for the plants' sites
  Field moisture_, slope_deg_;  // the conditions', for the sward on the open ground
  SeedMap seeds_;
  int regenerationX_ = 0, regenerationY_ = 0;  // regeneration cells over the map
  EcosystemState state_;
  std::uint64_t settledBelowId_ = 0;  // the plants below this id are in order of place
  // This year's trees, the crowns of its light (findTrees), in plant order, and per tree: its
  // crown's leaf area, and the foliage it holds until it has grown, then what its production
  // left of its upkeep (carbonDeficit()), for mortality: its growth reads the one for the
  // last time where it writes the other. Per tree, not per plant: most of a young
  // landscape's 100 million plants are saplings.
  Buffer<std::uint32_t> trees_;
  Buffer<float> leafArea_m2_, foliageThenDeficit_;
  Buffer<std::uint8_t> recruited_;  // per plant: grew out of the sapling layer this year
  // Per regeneration cell: one of its young plants grew out of the layer this year (a flag a
  // cell: a lookup per young plant, where a list of the cells cost a search).
  Buffer<std::uint8_t> clearedCells_;
  std::vector<int> born_, died_, plantedDied_;
  std::function<bool(glm::dvec2)> isOpen_;
  std::vector<std::uint8_t> openCell_;  // per regeneration cell: its centre is kept open
  // What a regeneration cell holds in its sapling layer (establish). Made afresh each year
  // and freed after: a landscape's 26 million cells take 0.2 GB that its year's light and
  // growth do not need.
  struct YoungPlants {
    std::uint8_t count = 0;
    bool closed = false;  // one of them has passed breast height
    std::array<std::uint8_t, kYoungPlantsPerCell> species{};
    bool holds(std::size_t s) const {
      return std::find(species.begin(), species.begin() + count, s) != species.begin() + count;
    }
  };
  struct SeedSourceForest {
    int region;  // SeedMap's
    double cover;
    std::vector<double> shares;
  };
  std::vector<SeedSourceForest> seedSources_;
};

}  // namespace eco
