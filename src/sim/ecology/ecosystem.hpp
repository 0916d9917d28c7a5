// The afforestation simulation (docs/ecology.md): plants on a terrain, stepped a year at a
// time through light, vigor, growth, mortality, reproduction and establishment. Every
// random number is keyed by (scenario seed, year, plant or cell id, purpose), and every
// pass keeps the plants' order, so a run gives the same plants whatever the thread count.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "model/species.hpp"
#include "sim/ecology/canopy_light.hpp"
#include "sim/ecology/plants.hpp"
#include "sim/ecology/species_ecology.hpp"
#include "sim/scenario.hpp"

namespace eco {

struct EcosystemSpecies {
  Species species;  // its tree model
  Ecology ecology;  // its niche and life history: the file's [ecology]
  double seedRainPerHaPerYear = 0.0;
  Field suitability;  // site suitability per cell
};

// A species file with its [ecology] table (an InputError at `where` when it has none), for
// the caller to add seed rain and suitability.
EcosystemSpecies readEcosystemSpecies(const std::filesystem::path& file,
                                      const SourceLocation& where);

struct EcosystemSettings {
  std::uint64_t seed = Scenario{}.seed;
  double latitude_deg = Climate{}.latitude_deg;
  double windFrom_deg = Climate{}.prevailingWindFrom_deg;
  SimulationSettings simulation;
};

// The state a checkpoint must hold to continue a run exactly.
struct EcosystemState {
  int year = 0;
  std::uint64_t nextId = 1;
  Plants plants;
};

class Ecosystem {
 public:
  // The terrain must outlive the ecosystem; each species brings its site suitability.
  Ecosystem(const Terrain& terrain, std::vector<EcosystemSpecies> species,
            const EcosystemSettings& settings);

  // Advances one year; afterwards year() is one higher and bornLastYear()/diedLastYear()
  // hold that year's counts per species.
  void step();

  // Adds a plant of `age` years grown at full vigor (sources for tests, planted stands).
  void plant(int species, double east_m, double north_m, int age_years);

  int year() const { return state_.year; }
  const Plants& plants() const { return state_.plants; }
  const std::vector<EcosystemSpecies>& species() const { return species_; }
  const std::vector<int>& bornLastYear() const { return born_; }
  const std::vector<int>& diedLastYear() const { return died_; }
  int stemsPerCell() const { return stemsPerCell_; }
  int seedlingsPerCell() const { return seedlingsPerCell_; }
  const Grid& grid() const { return terrain_.grid; }
  const Terrain& terrain() const { return terrain_; }

  // The light at the ground (0.5 m up) in the middle of a cell under this year's crowns.
  double groundLight(std::size_t cell);

  const EcosystemState& state() const { return state_; }
  void restore(EcosystemState state);

 private:
  struct Seed {
    std::int32_t cell;
    std::uint8_t species;
    float east_m, north_m;
    double draw;  // the uniform deviate that decides establishment
  };

  void buildCrowns();
  void computeLightAndGrow();
  void applyMortality();
  void promoteSaplings(const std::vector<float>& heightBefore);
  std::vector<Seed> disperseSeeds(const std::vector<int>& seedlingsInCell);
  void establish(std::vector<Seed> seeds, std::vector<int>& seedlingsInCell);
  void ensureGroundLight(std::vector<std::int32_t> cells);
  std::size_t addPlant(int species, double east_m, double north_m);

  const Terrain& terrain_;
  std::vector<EcosystemSpecies> species_;
  EcosystemSettings settings_;
  LightDirections sky_;
  CanopyScene scene_;
  int stemsPerCell_ = 1;
  int seedlingsPerCell_ = 1;
  EcosystemState state_;
  std::vector<float> groundLight_;  // per cell, NaN where not computed this year
  std::vector<std::int32_t> groundLightCells_;
  std::vector<int> born_, died_;
};

}  // namespace eco
