#include "sim/ecology/ecosystem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "core/frames.hpp"
#include "core/random.hpp"
#include "sim/ecology/dispersal.hpp"
#include "sim/ecology/growth.hpp"

namespace eco {
namespace {

constexpr float kGroundLightHeight_m = 0.5f;
// Plants are processed in fixed chunks whose results are joined in order, so the outcome
// does not depend on how TBB spreads the chunks over threads.
constexpr std::size_t kChunk = 1024;

}  // namespace

EcosystemSpecies readEcosystemSpecies(const std::filesystem::path& file,
                                      const SourceLocation& where) {
  if (!std::filesystem::is_regular_file(file))
    throw InputError(where, "species file not found: " + file.string());
  EcosystemSpecies s;
  s.species = loadSpecies(file);
  std::optional<Ecology> ecology = readEcology(file);
  if (!ecology)
    throw InputError(where, "species file " + file.string() +
                                " has no [ecology] table, so it cannot grow in an ecosystem "
                                "(docs/ecology.md)");
  s.ecology = std::move(*ecology);
  return s;
}

namespace {

const LifeHistory& lifeOf(const EcosystemSpecies& s) {
  return s.ecology.life;
}

template <typename F>
void forEachChunk(std::size_t count, F&& f) {
  const std::size_t chunks = (count + kChunk - 1) / kChunk;
  tbb::parallel_for(std::size_t{0}, chunks,
                    [&](std::size_t c) { f(c, c * kChunk, std::min(count, (c + 1) * kChunk)); });
}

}  // namespace

Ecosystem::Ecosystem(const Terrain& terrain, std::vector<EcosystemSpecies> species,
                     const EcosystemSettings& settings)
    : terrain_(terrain),
      species_(std::move(species)),
      settings_(settings),
      sky_(makeLightDirections(settings.latitude_deg, settings.simulation.lightDirections)),
      scene_(terrain),
      groundLight_(terrain.grid.cellCount(), std::numeric_limits<float>::quiet_NaN()),
      born_(species_.size(), 0),
      died_(species_.size(), 0) {
  ECO_ASSERT(species_.size() <= 255, "at most 255 species, got " << species_.size());
  for (const EcosystemSpecies& s : species_)
    ECO_ASSERT(s.suitability.size() == terrain.grid.cellCount(),
               "species " << s.species.name << " lacks its suitability field");
  const double cellArea_ha = terrain.grid.dx_m * terrain.grid.dy_m / 1e4;
  auto perCell = [&](double perHa) {
    return std::max(1, static_cast<int>(std::lround(perHa * cellArea_ha)));
  };
  stemsPerCell_ = perCell(settings.simulation.maxStemsPerHa);
  seedlingsPerCell_ = perCell(settings.simulation.maxSeedlingsPerHa);
}

void Ecosystem::restore(EcosystemState state) {
  state_ = std::move(state);
}

std::size_t Ecosystem::addPlant(int species, double east_m, double north_m) {
  Plants& p = state_.plants;
  const std::size_t i = p.size();
  p.resize(i + 1);
  const LifeHistory& life = lifeOf(species_[species]);
  p.id[i] = state_.nextId++;
  p.species[i] = static_cast<std::uint8_t>(species);
  p.east_m[i] = static_cast<float>(east_m);
  p.north_m[i] = static_cast<float>(north_m);
  p.ground_m[i] = terrain_.altitudeAt(east_m, north_m);
  const long cell = terrain_.grid.cellAt(static_cast<float>(east_m), static_cast<float>(north_m));
  ECO_ASSERT(cell >= 0, "a plant off the map at " << east_m << ", " << north_m);
  p.cell[i] = static_cast<std::int32_t>(cell);
  p.age_years[i] = 0;
  p.height_m[i] = static_cast<float>(life.seedlingHeight_m);
  p.dbh_m[i] = 0.0f;
  p.crownRadius_m[i] = static_cast<float>(crownRadiusOf(life, 0.0, life.seedlingHeight_m));
  p.vigor[i] = 1.0f;
  p.light[i] = 1.0f;
  p.variantSeed[i] = streamKey(settings_.seed, p.id[i], purpose("variant"));
  p.stressYears[i] = 0;
  p.alive[i] = 1;
  return i;
}

void Ecosystem::plant(int species, double east_m, double north_m, int age_years) {
  if (terrain_.grid.cellAt(static_cast<float>(east_m), static_cast<float>(north_m)) < 0)
    throw InputError({}, "a plant must stand on the terrain");
  const std::size_t i = addPlant(species, east_m, north_m);
  Plants& p = state_.plants;
  const LifeHistory& life = lifeOf(species_[species]);
  p.age_years[i] = age_years;
  p.height_m[i] = static_cast<float>(std::max(life.height_m.at(age_years), life.seedlingHeight_m));
  if (p.height_m[i] >= kBreastHeight_m) {
    // Diameter starts when the plant reaches breast height.
    const double youngest = life.height_m.ageOf(kBreastHeight_m);
    p.dbh_m[i] = static_cast<float>(life.dbh_m.at(age_years - youngest));
  }
  p.crownRadius_m[i] = static_cast<float>(crownRadiusOf(life, p.dbh_m[i], p.height_m[i]));
}

void Ecosystem::buildCrowns() {
  const Plants& p = state_.plants;
  std::vector<float> crownDepth;  // optical depth along a whole crown's length, per species
  for (const EcosystemSpecies& s : species_)
    crownDepth.push_back(
        static_cast<float>(-std::log(std::max(lifeOf(s).crownTransmittance, 1e-4))));
  std::vector<Crown> crowns;
  crowns.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.height_m[i] < kBreastHeight_m) continue;
    const LifeHistory& life = lifeOf(species_[p.species[i]]);
    const float length = static_cast<float>(life.crownRatio) * p.height_m[i];
    Crown c;
    c.centre = {p.east_m[i], p.north_m[i], p.ground_m[i] + p.height_m[i] - 0.5f * length};
    c.radius_m = std::max(p.crownRadius_m[i], 0.05f);
    c.halfLength_m = 0.5f * length;
    c.opticalDepthPerMetre = crownDepth[p.species[i]] / length;
    c.owner = static_cast<int>(i);
    crowns.push_back(c);
  }
  scene_.setCrowns(std::move(crowns));
  for (std::int32_t cell : groundLightCells_)
    groundLight_[cell] = std::numeric_limits<float>::quiet_NaN();
  groundLightCells_.clear();
}

double Ecosystem::groundLight(std::size_t cell) {
  if (std::isnan(groundLight_[cell])) ensureGroundLight({static_cast<std::int32_t>(cell)});
  return groundLight_[cell];
}

void Ecosystem::ensureGroundLight(std::vector<std::int32_t> cells) {
  std::erase_if(cells, [&](std::int32_t c) { return !std::isnan(groundLight_[c]); });
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  const Grid& g = terrain_.grid;
  std::vector<LightProbe> probes(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const int x = static_cast<int>(cells[k] % g.width), y = static_cast<int>(cells[k] / g.width);
    probes[k].point = {g.eastOf(x), g.northOf(y), terrain_.heightAt(x, y) + kGroundLightHeight_m};
  }
  const std::vector<float> light = scene_.lightAt(probes, sky_);
  for (std::size_t k = 0; k < cells.size(); ++k) groundLight_[cells[k]] = light[k];
  groundLightCells_.insert(groundLightCells_.end(), cells.begin(), cells.end());
}

void Ecosystem::computeLightAndGrow() {
  Plants& p = state_.plants;
  const std::vector<float> heightBefore = p.height_m;
  std::vector<std::int32_t> understorey;
  std::vector<LightProbe> crownTops;
  std::vector<std::uint32_t> stems;
  const auto refresh = static_cast<std::uint64_t>(settings_.simulation.lightRefreshYears);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.height_m[i] < kBreastHeight_m) {
      understorey.push_back(p.cell[i]);
    } else if ((p.id[i] + static_cast<std::uint64_t>(state_.year)) % refresh == 0) {
      crownTops.push_back({{p.east_m[i], p.north_m[i], p.ground_m[i] + p.height_m[i] + 0.01f},
                           static_cast<int>(i)});
      stems.push_back(static_cast<std::uint32_t>(i));
    }
  }
  ensureGroundLight(std::move(understorey));
  const std::vector<float> stemLight = scene_.lightAt(crownTops, sky_);
  for (std::size_t k = 0; k < stems.size(); ++k) p.light[stems[k]] = stemLight[k];
  tbb::parallel_for(std::size_t{0}, p.size(), [&](std::size_t i) {
    const EcosystemSpecies& s = species_[p.species[i]];
    const LifeHistory& life = lifeOf(s);
    if (p.height_m[i] < kBreastHeight_m) p.light[i] = groundLight_[p.cell[i]];
    const double lightVigor = std::clamp(s.ecology.lightResponse(p.light[i]), 0.0, 1.0);
    const double vigor = std::min<double>(s.suitability[p.cell[i]], lightVigor);
    p.vigor[i] = static_cast<float>(vigor);
    const double height = grownValue(life.height_m, p.height_m[i], vigor);
    if (height >= kBreastHeight_m)
      p.dbh_m[i] = static_cast<float>(grownValue(life.dbh_m, p.dbh_m[i], vigor));
    p.height_m[i] = static_cast<float>(height);
    p.crownRadius_m[i] = static_cast<float>(crownRadiusOf(life, p.dbh_m[i], height));
    p.age_years[i] += 1;
    p.stressYears[i] = vigor < life.stressVigor
                           ? static_cast<std::uint16_t>(std::min(p.stressYears[i] + 1, 60000))
                           : std::uint16_t{0};
  });
  promoteSaplings(heightBefore);
}

// A sapling grows past breast height into the canopy layer only where its cell has room
// there; otherwise it waits just below, as advance regeneration, until a stem dies.
void Ecosystem::promoteSaplings(const std::vector<float>& heightBefore) {
  Plants& p = state_.plants;
  std::vector<int> stems(terrain_.grid.cellCount(), 0);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (heightBefore[i] >= kBreastHeight_m) ++stems[p.cell[i]];
  // The most vigorous saplings take the free places first: under a light canopy a
  // shade-tolerant sapling outgrows a light-demanding one.
  std::vector<std::uint32_t> candidates;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (heightBefore[i] < kBreastHeight_m && p.height_m[i] >= kBreastHeight_m)
      candidates.push_back(static_cast<std::uint32_t>(i));
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return p.vigor[a] > p.vigor[b]; });
  for (std::uint32_t i : candidates) {
    if (stems[p.cell[i]] < stemsPerCell_) {
      ++stems[p.cell[i]];
      continue;
    }
    const LifeHistory& life = lifeOf(species_[p.species[i]]);
    p.height_m[i] = std::nextafter(static_cast<float>(kBreastHeight_m), 0.0f);
    p.dbh_m[i] = 0.0f;
    p.crownRadius_m[i] = static_cast<float>(crownRadiusOf(life, 0.0, p.height_m[i]));
  }
}

void Ecosystem::applyMortality() {
  Plants& p = state_.plants;
  tbb::parallel_for(std::size_t{0}, p.size(), [&](std::size_t i) {
    const LifeHistory& life = lifeOf(species_[p.species[i]]);
    Rng rng(streamKey(settings_.seed, state_.year, p.id[i], purpose("mortality")));
    if (rng.uniform() < mortalityProbability(life, p.age_years[i], p.stressYears[i]))
      p.alive[i] = 0;
  });
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!p.alive[i]) ++died_[p.species[i]];
  p.removeDead();
}

std::vector<Ecosystem::Seed> Ecosystem::disperseSeeds(const std::vector<int>& seedlingsInCell) {
  const Plants& p = state_.plants;
  const Grid& g = terrain_.grid;
  const glm::dvec2 downwind = mapDownwindOf(settings_.windFrom_deg);
  // Only seeds that germinate are followed (a binomial thinning by the germination rate,
  // drawn with the seed count); one is kept if it could establish: on the map, in a cell
  // with room, and with its establishment draw below the site suitability (light can only
  // lower the chance further, so dropping the others now changes nothing).
  auto consider = [&](int species, double eastExact, double northExact, double draw,
                      std::vector<Seed>& out) {
    // Plants store float positions: the cell must be the one of the rounded position.
    const float east = static_cast<float>(eastExact), north = static_cast<float>(northExact);
    const long cell = g.cellAt(east, north);
    if (cell < 0 || seedlingsInCell[cell] >= seedlingsPerCell_) return;
    const EcosystemSpecies& s = species_[species];
    if (draw >= s.suitability[cell]) return;
    out.push_back(
        {static_cast<std::int32_t>(cell), static_cast<std::uint8_t>(species), east, north, draw});
  };
  const std::size_t chunks = (p.size() + kChunk - 1) / kChunk;
  std::vector<std::vector<Seed>> perChunk(chunks);
  forEachChunk(p.size(), [&](std::size_t c, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const LifeHistory& life = lifeOf(species_[p.species[i]]);
      if (p.age_years[i] < life.maturityAge_years) continue;
      Rng rng(streamKey(settings_.seed, state_.year, p.id[i], purpose("seeds")));
      const int count =
          rng.stochasticRound(life.germination * seedCount(life, p.dbh_m[i], p.vigor[i]));
      for (int k = 0; k < count; ++k) {
        const glm::dvec2 offset = seedOffset(life, downwind, rng);
        consider(p.species[i], p.east_m[i] + offset.x, p.north_m[i] + offset.y, rng.uniform(),
                 perChunk[c]);
      }
    }
  });
  std::vector<Seed> seeds;
  for (std::vector<Seed>& chunk : perChunk) seeds.insert(seeds.end(), chunk.begin(), chunk.end());
  // Background seed rain from outside the map, evenly over it.
  const double area_ha = g.area_m2() / 1e4;
  const double width_m = g.width * g.dx_m, height_m = g.height * g.dy_m;
  for (std::size_t s = 0; s < species_.size(); ++s) {
    Rng rng(streamKey(settings_.seed, state_.year, s, purpose("seed rain")));
    const int count = rng.stochasticRound(lifeOf(species_[s]).germination *
                                          species_[s].seedRainPerHaPerYear * area_ha);
    for (int k = 0; k < count; ++k) {
      const double east = rng.uniform() * width_m - 0.5 * g.dx_m;
      const double north = rng.uniform() * height_m - 0.5 * g.dy_m;
      consider(static_cast<int>(s), east, north, rng.uniform(), seeds);
    }
  }
  return seeds;
}

void Ecosystem::establish(std::vector<Seed> seeds, std::vector<int>& seedlingsInCell) {
  std::stable_sort(seeds.begin(), seeds.end(),
                   [](const Seed& a, const Seed& b) { return a.cell < b.cell; });
  std::vector<std::int32_t> cells;
  cells.reserve(seeds.size());
  for (const Seed& seed : seeds) cells.push_back(seed.cell);
  ensureGroundLight(std::move(cells));
  for (const Seed& seed : seeds) {
    if (seedlingsInCell[seed.cell] >= seedlingsPerCell_) continue;
    const EcosystemSpecies& s = species_[seed.species];
    const double light = groundLight_[seed.cell];
    const double chance =
        std::min<double>(s.suitability[seed.cell], s.ecology.lightResponse(light));
    if (seed.draw >= chance) continue;
    const std::size_t i = addPlant(seed.species, seed.east_m, seed.north_m);
    state_.plants.light[i] = static_cast<float>(light);
    state_.plants.vigor[i] = static_cast<float>(chance);
    ++seedlingsInCell[seed.cell];
    ++born_[seed.species];
  }
}

void Ecosystem::step() {
  ++state_.year;
  std::fill(born_.begin(), born_.end(), 0);
  std::fill(died_.begin(), died_.end(), 0);
  buildCrowns();
  computeLightAndGrow();
  applyMortality();
  std::vector<int> seedlingsInCell(terrain_.grid.cellCount(), 0);
  const Plants& p = state_.plants;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.height_m[i] < kBreastHeight_m) ++seedlingsInCell[p.cell[i]];
  establish(disperseSeeds(seedlingsInCell), seedlingsInCell);
}

}  // namespace eco
