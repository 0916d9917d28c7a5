#include "sim/ecology/ecosystem.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "core/frames.hpp"
#include "core/random.hpp"
#include "sim/ecology/growth.hpp"
#include "sim/ecology/seedbed.hpp"

namespace eco {
namespace {

// A crown keeps at least this share of the tree's height in leaves however dark it is
// below: the rest of its fate is its carbon balance's.
constexpr double kMinCrownShare = 0.1;
// Individuals of a species differ in how fast they grow, for their genotype and the
// microsite under them (soil depth, stones, a root's luck). The species' potential is what
// its best individuals reach (a yield table's top height); each plant falls short of it by a
// lasting factor 1 - spread |z|, z standard normal within 3 (ours, docs/ecology.md). Without
// it a planted stand of identical trees would never differentiate and never thin itself.
constexpr double kGrowthFactorSpread = 0.15;

using Age = decltype(Plants::age_years)::value_type;
static_assert(kLongestLife_years <= std::numeric_limits<Age>::max());

// An age given to a plant (a source's grown tree, planted stock) as the plants keep it.
Age ageOf(int age_years) {
  ECO_ASSERT(age_years >= 0 && age_years <= kLongestLife_years,
             "a plant's age of " << age_years << " years");
  return static_cast<Age>(age_years);
}

Field terrainLightOf(const ConditionFields& fields) {
  Field light(fields.sunniness.size());
  // Outside the landscape (no-data cells, whose conditions are NaN) the sky is open.
  for (std::size_t c = 0; c < light.size(); ++c)
    light[c] =
        std::isfinite(fields.sunniness[c]) ? static_cast<float>(fields.terrainLight(c)) : 1.0f;
  return light;
}

std::vector<const LifeHistory*> livesOf(const std::vector<EcosystemSpecies>& species) {
  std::vector<const LifeHistory*> lives;
  for (const EcosystemSpecies& s : species) lives.push_back(&s.ecology.life);
  return lives;
}

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

Ecosystem::Ecosystem(const Terrain& terrain, const ConditionFields& fields,
                     std::vector<EcosystemSpecies> species, const EcosystemSettings& settings)
    : terrain_(terrain),
      species_(std::move(species)),
      settings_(settings),
      downwind_(mapDownwindOf(settings.windFrom_deg)),
      light_(terrain.grid, terrainLightOf(fields)),
      windiness_(fields.windiness),
      moisture_(fields.moisture),
      slope_deg_(fields.slope_deg),
      seeds_(terrain.grid, livesOf(species_), downwind_),
      regenerationX_(static_cast<int>(
          std::ceil(terrain.grid.width * terrain.grid.dx_m / kRegenerationCell_m))),
      regenerationY_(static_cast<int>(
          std::ceil(terrain.grid.height * terrain.grid.dy_m / kRegenerationCell_m))),
      born_(species_.size(), 0),
      died_(species_.size(), 0),
      plantedDied_(species_.size(), 0) {
  ECO_ASSERT(species_.size() <= 255, "at most 255 species, got " << species_.size());
  for (const EcosystemSpecies& s : species_) {
    ECO_ASSERT(s.suitability.size() == terrain.grid.cellCount(),
               "species " << s.species.name << " lacks its suitability field");
    seedlingCrownLimit_m_.push_back(seedlingCrownRadiusLimit(s.ecology.life));
    foliageLimit_.push_back(foliageLimitOf(s.ecology.life));
  }
}

void Ecosystem::restore(EcosystemState state) {
  state_ = std::move(state);
  // A checkpoint holds the plants in order of place; one edited by hand need not, and is put
  // in that order here.
  settledBelowId_ = 0;
  settleNewcomers();
}

void Ecosystem::settleNewcomers() {
  Plants& p = state_.plants;
  // The newcomers were appended, so they are the last rows; their ids are the newest.
  std::size_t first = p.size();
  while (first > 0 && p.id[first - 1] >= settledBelowId_) --first;
  p.settleTail(first, [&](std::size_t i) {
    return std::pair(light_.columnAt(p.east_m[i], p.north_m[i]), p.id[i]);
  });
  settledBelowId_ = state_.nextId;
}

double Ecosystem::lightAt(double east_m, double north_m, double height_m) const {
  return light_.lightAt(east_m, north_m, height_m);
}

std::vector<PlantSite> Ecosystem::sitesOf(const Plants& plants) const {
  // Before the first year there is no canopy: every site is neutral.
  if (!lightComputed_) return std::vector<PlantSite>(plants.size());
  return plantSites(plants, light_, terrain_.grid, windiness_, settings_.windFrom_deg);
}

PlantSite Ecosystem::siteOf(const Plants& plants, std::size_t i) const {
  if (!lightComputed_) return {};
  return plantSite(plants, i, light_, terrain_.grid, windiness_, downwind_);
}

std::size_t Ecosystem::cellOf(const Plants& plants, std::size_t i) const {
  const long cell = terrain_.grid.cellAt(plants.east_m[i], plants.north_m[i]);
  ECO_ASSERT(cell >= 0, "plant " << plants.id[i] << " is off the map");
  return static_cast<std::size_t>(cell);
}

float Ecosystem::groundOf(const Plants& plants, std::size_t i) const {
  return terrain_.altitudeAt(plants.east_m[i], plants.north_m[i]);
}

std::uint32_t Ecosystem::variantSeedOf(std::uint64_t id) const {
  return static_cast<std::uint32_t>(streamKey(settings_.seed, id, purpose("variant")) >> 32);
}

std::size_t Ecosystem::addPlant(int species, double east_m, double north_m) {
  const std::size_t i = state_.plants.size();
  state_.plants.resize(i + 1);
  setSeedling(i, state_.nextId++, species, east_m, north_m);
  return i;
}

void Ecosystem::setSeedling(std::size_t i, std::uint64_t id, int species, double east_m,
                            double north_m) {
  Plants& p = state_.plants;
  const LifeHistory& life = species_[species].ecology.life;
  p.id[i] = id;
  p.species[i] = static_cast<std::uint8_t>(species);
  p.east_m[i] = static_cast<float>(east_m);
  p.north_m[i] = static_cast<float>(north_m);
  ECO_ASSERT(terrain_.grid.cellAt(p.east_m[i], p.north_m[i]) >= 0,
             "a plant off the map at " << east_m << ", " << north_m);
  p.age_years[i] = 0;
  p.height_m[i] = static_cast<float>(life.seedlingHeight_m);
  p.dbh_m[i] = 0.0f;
  p.crownBase_m[i] = 0.0f;
  p.crownRadius_m[i] = static_cast<float>(crownRadiusOf(life, 0.0, life.seedlingHeight_m));
  p.vigor[i] = 1.0f;
  p.light[i] = 1.0f;
  Rng rng(streamKey(settings_.seed, p.id[i], purpose("growth factor")));
  p.growthFactor[i] =
      static_cast<float>(1.0 - kGrowthFactorSpread * std::min(std::abs(rng.normal()), 3.0));
  p.stressYears[i] = 0;
  p.origin[i] = static_cast<std::uint8_t>(PlantOrigin::Seeded);
  p.alive[i] = 1;
}

glm::dvec2 Ecosystem::regenerationOrigin() const {
  return {-0.5 * grid().dx_m, -0.5 * grid().dy_m};
}

std::size_t Ecosystem::regenerationCellOf(double east_m, double north_m) const {
  const glm::dvec2 origin = regenerationOrigin();
  const int x = std::clamp(static_cast<int>((east_m - origin.x) / kRegenerationCell_m), 0,
                           regenerationX_ - 1);
  const int y = std::clamp(static_cast<int>((north_m - origin.y) / kRegenerationCell_m), 0,
                           regenerationY_ - 1);
  return static_cast<std::size_t>(y) * regenerationX_ + x;
}

glm::dvec2 Ecosystem::regenerationCentre(int x, int y) const {
  const glm::dvec2 origin = regenerationOrigin();
  return {origin.x + (x + 0.5) * kRegenerationCell_m, origin.y + (y + 0.5) * kRegenerationCell_m};
}

void Ecosystem::plant(int species, double east_m, double north_m, int age_years) {
  if (terrain_.grid.cellAt(static_cast<float>(east_m), static_cast<float>(north_m)) < 0)
    throw InputError({}, "a plant must stand on the terrain");
  const std::size_t i = addPlant(species, east_m, north_m);
  Plants& p = state_.plants;
  const LifeHistory& life = species_[species].ecology.life;
  // Grown alone: a sapling at its potential, then a tree with its whole crown in the light.
  double height = life.seedlingHeight_m, dbh = 0.0;
  for (int year = 0; year < age_years; ++year) {
    if (height < kRegenerationHeight_m) {
      height = growSapling(life, height, {}).height_m;
      if (height >= kBreastHeight_m) dbh = saplingDiameter(life, height);
      continue;
    }
    const double radius = crownRadiusOf(life, dbh, height);
    const CrownFoliage foliage = crownFoliage(life, foliageLimit_[species], dbh, radius, 1.0);
    const CrownShape crown{0.0f, 0.0f, static_cast<float>(radius), static_cast<float>(height),
                           static_cast<float>(foliage.leafArea_m2)};
    GrowingConditions conditions;
    conditions.aging = agingFactor(life, height, year + 1);
    const TreeYear grown = growTree(life, dbh, height, foliage.foliage_kg,
                                    LightGrid::absorbedInTheOpen(crown), conditions);
    dbh = grown.dbh_m;
    height = grown.height_m;
  }
  p.age_years[i] = ageOf(age_years);
  p.height_m[i] = static_cast<float>(height);
  p.dbh_m[i] = static_cast<float>(dbh);
  p.crownBase_m[i] =
      height >= kBreastHeight_m ? static_cast<float>((1.0 - life.crownRatio) * height) : 0.0f;
  p.crownRadius_m[i] = static_cast<float>(crownRadiusOf(life, dbh, height));
}

void Ecosystem::plantSapling(int species, double east_m, double north_m, double height_m,
                             int age_years, PlantOrigin origin) {
  const std::size_t i = addPlant(species, east_m, north_m);
  Plants& p = state_.plants;
  // A sapling of the layer, below 4 m (the float below it: the double below 4 rounds to 4 as
  // a float).
  setSaplingHeight(i, std::min(static_cast<float>(height_m),
                               std::nextafter(static_cast<float>(kRegenerationHeight_m), 0.0f)));
  p.age_years[i] = ageOf(age_years);
  p.origin[i] = static_cast<std::uint8_t>(origin);
}

void Ecosystem::setSaplingHeight(std::size_t i, double height_m) {
  Plants& p = state_.plants;
  const LifeHistory& life = species_[p.species[i]].ecology.life;
  p.height_m[i] = static_cast<float>(height_m);
  if (height_m >= kBreastHeight_m) {
    p.dbh_m[i] = static_cast<float>(saplingDiameter(life, height_m));
    p.crownBase_m[i] = 0.0f;
    p.crownRadius_m[i] = static_cast<float>(crownRadiusOf(life, p.dbh_m[i], p.height_m[i]));
  } else {
    // crownRadiusOf's below breast height, without its exp and two logs.
    p.crownRadius_m[i] =
        static_cast<float>(std::min(seedlingCrownLimit_m_[p.species[i]], 0.5 * p.height_m[i]));
  }
}

void Ecosystem::removePlants(const std::vector<std::uint8_t>& removed) {
  Plants& p = state_.plants;
  ECO_ASSERT(removed.size() == p.size(), "one flag per plant");
  for (std::size_t i = 0; i < p.size(); ++i)
    if (removed[i]) p.alive[i] = 0;
  p.removeDead();
}

void Ecosystem::keepOpen(std::function<bool(glm::dvec2)> isOpen) {
  isOpen_ = std::move(isOpen);
  openCell_.assign(static_cast<std::size_t>(regenerationX_) * regenerationY_, 0);
  tbb::parallel_for(0, regenerationY_, [&](int y) {
    for (int x = 0; x < regenerationX_; ++x)
      openCell_[static_cast<std::size_t>(y) * regenerationX_ + x] =
          isOpen_(regenerationCentre(x, y));
  });
}

bool Ecosystem::addSeedSource(const std::function<bool(glm::dvec2)>& covered, double cover,
                              std::vector<double> shares) {
  ECO_ASSERT(shares.size() == species_.size(), "a share per species");
  const int region = seeds_.addSourceRegion(covered);
  if (!seeds_.regionReachesTheMap(region)) return false;
  seedSources_.push_back({region, cover, std::move(shares)});
  return true;
}

CrownColumns Ecosystem::crownsOf(const Plants& p) const {
  return {p.east_m, p.north_m, p.crownRadius_m, p.height_m, trees_, leafArea_m2_};
}

void Ecosystem::findTrees() {
  const Plants& p = state_.plants;
  ECO_ASSERT(p.size() <= std::numeric_limits<std::uint32_t>::max(),
             "more plants than 32-bit rows index");
  // Block by block side by side: each block's count, then its rows in order.
  std::vector<std::size_t> blockStart(plantBlocks(p.size()) + 1, 0);
  forEachPlantBlock(p.size(), [&](std::size_t block, std::size_t first, std::size_t end) {
    blockStart[block + 1] = static_cast<std::size_t>(
        std::count_if(p.height_m.begin() + static_cast<std::ptrdiff_t>(first),
                      p.height_m.begin() + static_cast<std::ptrdiff_t>(end),
                      [](float h) { return h >= kRegenerationHeight_m; }));
  });
  std::partial_sum(blockStart.begin(), blockStart.end(), blockStart.begin());
  resizeForOverwrite(trees_, blockStart.back());
  forEachPlantBlock(p.size(), [&](std::size_t block, std::size_t first, std::size_t end) {
    std::size_t k = blockStart[block];
    for (std::size_t i = first; i < end; ++i)
      if (p.height_m[i] >= kRegenerationHeight_m) trees_[k++] = static_cast<std::uint32_t>(i);
  });
}

void Ecosystem::computeLight() {
  const Plants& p = state_.plants;
  findTrees();
  resizeForOverwrite(leafArea_m2_, trees_.size());
  resizeForOverwrite(foliageThenDeficit_, trees_.size());
  // Each tree's crown spreads its foliage as last year's light at its top built the leaves.
  tbb::parallel_for(std::size_t{0}, trees_.size(), [&](std::size_t k) {
    const std::size_t i = trees_[k];
    const LifeHistory& life = species_[p.species[i]].ecology.life;
    // The leaves spread over the crown as the light model draws it, so its leaf area index
    // there is the one they were spread to.
    const float radius = std::max(p.crownRadius_m[i], kMinCrownRadius_m);
    const CrownFoliage foliage =
        crownFoliage(life, foliageLimit_[p.species[i]], p.dbh_m[i], radius, p.light[i]);
    leafArea_m2_[k] = static_cast<float>(foliage.leafArea_m2);
    foliageThenDeficit_[k] = static_cast<float>(foliage.foliage_kg);
  });
  light_.compute(crownsOf(p));
  lightComputed_ = true;
}

void Ecosystem::grow() {
  Plants& p = state_.plants;
  // The sapling layer, as iLand's: in height only, by the light the trees' crowns leave on
  // the ground (the layer casts no shade), its diameter the sapling height/diameter ratio's
  // from breast height on. The trees of this year's light are grown below.
  resizeForOverwrite(recruited_, p.size());
  clearedCells_.assign(static_cast<std::size_t>(regenerationX_) * regenerationY_, 0);
  tbb::parallel_for(std::size_t{0}, p.size(), [&](std::size_t i) {
    recruited_[i] = 0;
    if (p.height_m[i] >= kRegenerationHeight_m) return;
    const EcosystemSpecies& s = species_[p.species[i]];
    const LifeHistory& life = s.ecology.life;
    const double suitability = s.suitability[cellOf(p, i)];
    p.age_years[i] += 1;
    const double light = light_.groundLightAt(p.east_m[i], p.north_m[i]);
    const double response = std::clamp(s.ecology.lightResponse(light), 0.0, 1.0);
    const SaplingYear year =
        growSapling(life, p.height_m[i], {suitability, response, p.growthFactor[i]});
    // Counted up to the most a species may give: no more is needed to tell.
    p.stressYears[i] =
        year.poor
            ? static_cast<std::uint8_t>(std::min(p.stressYears[i] + 1, kMostSaplingStressYears))
            : std::uint8_t{0};
    setSaplingHeight(i, year.height_m);
    p.vigor[i] = static_cast<float>(suitability * response);
    p.light[i] = static_cast<float>(light);
    recruited_[i] = p.height_m[i] >= kRegenerationHeight_m;  // next year's tree (findTrees)
    if (recruited_[i])                                       // set by each of a cell's recruits
      std::atomic_ref(clearedCells_[regenerationCellOf(p.east_m[i], p.north_m[i])])
          .store(1, std::memory_order_relaxed);
  });
  const CrownColumns crowns = crownsOf(p);  // as the light grid drew them
  tbb::parallel_for(std::size_t{0}, trees_.size(), [&](std::size_t k) {
    const std::size_t i = trees_[k];
    const EcosystemSpecies& s = species_[p.species[i]];
    const LifeHistory& life = s.ecology.life;
    const double suitability = s.suitability[cellOf(p, i)];
    p.age_years[i] += 1;
    const CrownShape crown = crowns[k];  // read before this year's growth changes the row
    const double absorbed = light_.absorbed(k);
    const double open = LightGrid::absorbedInTheOpen(crown);
    const double relative = open > 0.0 ? std::min(1.0, absorbed / open) : 0.0;
    const double topLight = light_.lightAt(p.east_m[i], p.north_m[i], p.height_m[i] + 0.5);
    // Height growth answers the light the whole crown gets, relative to the open.
    const double response = std::clamp(s.ecology.lightResponse(relative), 0.0, 1.0);
    const TreeYear year =
        growTree(life, p.dbh_m[i], p.height_m[i], foliageThenDeficit_[k], absorbed,
                 {suitability, response, p.growthFactor[i],
                  agingFactor(life, p.height_m[i], p.age_years[i])});
    foliageThenDeficit_[k] = static_cast<float>(year.carbonDeficit());  // the foliage read above
    // The branches that this year's light beside the crown left below the compensation point
    // die.
    const double pruned = light_.heightWithSideLight(
        p.east_m[i], p.north_m[i], LightGrid::beyondCrown_m(p.crownRadius_m[i]), p.crownBase_m[i],
        p.height_m[i], leafCompensationLight(life));
    p.crownBase_m[i] = static_cast<float>(std::min(std::max<double>(p.crownBase_m[i], pruned),
                                                   (1.0 - kMinCrownShare) * year.height_m));
    p.dbh_m[i] = static_cast<float>(year.dbh_m);
    p.height_m[i] = static_cast<float>(year.height_m);
    p.crownRadius_m[i] = static_cast<float>(crownRadiusOf(life, year.dbh_m, year.height_m));
    p.vigor[i] = static_cast<float>(relative * suitability);
    p.light[i] = static_cast<float>(topLight);
  });
}

void Ecosystem::produceSeeds() {
  const Plants& p = state_.plants;
  seeds_.clear();
  std::vector<char> mast(species_.size());
  for (std::size_t s = 0; s < species_.size(); ++s) {
    Rng rng(streamKey(settings_.seed, state_.year, s, purpose("mast year")));
    mast[s] = rng.uniform() * species_[s].ecology.life.mastIntervalYears < 1.0;
  }
  // The trees' seeds are worked out side by side and summed into the source cells in plant
  // order: the sums do not depend on the thread count.
  struct Fruiting {
    std::size_t plant;
    double seeds;
  };
  std::vector<std::vector<Fruiting>> fruiting(plantBlocks(p.size()));
  forEachPlantBlock(p.size(), [&](std::size_t block, std::size_t first, std::size_t end) {
    for (std::size_t i = first; i < end; ++i) {
      const LifeHistory& life = species_[p.species[i]].ecology.life;
      if (p.height_m[i] < kBreastHeight_m || p.age_years[i] < life.maturityAge_years) continue;
      const double suitability = species_[p.species[i]].suitability[cellOf(p, i)];
      const double relative = suitability > 0.0 ? p.vigor[i] / suitability : 0.0;
      const double seeds = seedProduction(life, p.crownRadius_m[i], mast[p.species[i]], relative);
      if (seeds > 0.0) fruiting[block].push_back({i, seeds});
    }
  });
  for (const std::vector<Fruiting>& block : fruiting)
    for (const Fruiting& tree : block)
      seeds_.addSeeds(p.species[tree.plant], p.east_m[tree.plant], p.north_m[tree.plant],
                      tree.seeds);
  // The forest around the map: a closed canopy of full-grown trees in the light, each
  // species fruiting on its share of the ground.
  for (std::size_t s = 0; s < species_.size(); ++s) {
    const LifeHistory& life = species_[s].ecology.life;
    if (species_[s].surroundingForestShare > 0.0)
      seeds_.setSurroundingSeeds(static_cast<int>(s), species_[s].surroundingForestShare *
                                                          seedsPerCrownArea(life, mast[s]));
    // The plan's forests ([[seed_source]]) likewise, on their own ground.
    for (const SeedSourceForest& forest : seedSources_)
      if (forest.shares[s] > 0.0)
        seeds_.addRegionSeeds(forest.region, static_cast<int>(s),
                              forest.cover * forest.shares[s] * seedsPerCrownArea(life, mast[s]));
  }
  seeds_.disperse();
}

void Ecosystem::applyMortality() {
  Plants& p = state_.plants;
  std::vector<double> intrinsic;
  for (const EcosystemSpecies& s : species_)
    intrinsic.push_back(intrinsicMortality(s.ecology.life));
  // Plant i dies by its own draw; a tree with this share of its upkeep unmade.
  auto mayDie = [&](std::size_t i, double carbonDeficit) {
    const LifeHistory& life = species_[p.species[i]].ecology.life;
    Rng rng(streamKey(settings_.seed, state_.year, p.id[i], purpose("mortality")));
    double chance = 0.0;
    if (p.origin[i] == static_cast<std::uint8_t>(PlantOrigin::PlantedRuledOut) ||
        p.age_years[i] >= life.maxAge_years)
      chance = 1.0;
    else if (p.height_m[i] >= kRegenerationHeight_m)  // treeMortality, intrinsic part once
      chance = std::min(1.0, intrinsic[p.species[i]] + starvationMortality(life, carbonDeficit));
    else
      chance = p.stressYears[i] >= life.saplingStressYears ? 1.0 : intrinsic[p.species[i]];
    if (rng.uniform() < chance) p.alive[i] = 0;
  };
  // The trees of this year's light, by their carbon balance; then the rest: the sapling
  // layer and the saplings that became trees this year, which had no crown (no deficit).
  // The seeded young plants that share a regeneration cell with one that became a tree this
  // year die (planted stock, which iLand plants as trees, stays), in the same pass.
  tbb::parallel_for(std::size_t{0}, trees_.size(),
                    [&](std::size_t k) { mayDie(trees_[k], foliageThenDeficit_[k]); });
  const bool anyRecruits = std::find(recruited_.begin(), recruited_.end(), 1) != recruited_.end();
  tbb::parallel_for(std::size_t{0}, p.size(), [&](std::size_t i) {
    if (recruited_[i]) return mayDie(i, 0.0);
    if (p.height_m[i] >= kRegenerationHeight_m) return;  // a tree of this year's light, above
    if (anyRecruits && p.origin[i] == static_cast<std::uint8_t>(PlantOrigin::Seeded) &&
        clearedCells_[regenerationCellOf(p.east_m[i], p.north_m[i])])
      p.alive[i] = 0;
    else
      mayDie(i, 0.0);
  });
  releaseTreeArrays();
  // The dead counted block by block side by side (whole numbers: in any order the same).
  const std::size_t species = species_.size();
  std::vector<int> blockDied(plantBlocks(p.size()) * 2 * species, 0);
  forEachPlantBlock(p.size(), [&](std::size_t block, std::size_t first, std::size_t end) {
    int* died = blockDied.data() + block * 2 * species;
    int* plantedDied = died + species;
    for (std::size_t i = first; i < end; ++i)
      if (!p.alive[i]) {
        ++died[p.species[i]];
        if (p.origin[i] != static_cast<std::uint8_t>(PlantOrigin::Seeded))
          ++plantedDied[p.species[i]];
      }
  });
  for (std::size_t block = 0; block < plantBlocks(p.size()); ++block)
    for (std::size_t s = 0; s < species; ++s) {
      died_[s] += blockDied[block * 2 * species + s];
      plantedDied_[s] += blockDied[block * 2 * species + species + s];
    }
  p.removeDead();
}

void Ecosystem::releaseTreeArrays() {
  light_.releaseAbsorbed();
  Buffer<std::uint32_t>().swap(trees_);
  Buffer<float>().swap(leafArea_m2_);
  Buffer<float>().swap(foliageThenDeficit_);
  Buffer<std::uint8_t>().swap(recruited_);
  Buffer<std::uint8_t>().swap(clearedCells_);
}

void Ecosystem::establish() {
  const Plants& p = state_.plants;
  const Grid& g = terrain_.grid;
  // The young plants are entered side by side: each claims a place in its cell atomically.
  // Whichever claims which place, a cell holds the same species (it is read as a set:
  // YoungPlants::holds), and one with more young plants than places is closed.
  std::vector<YoungPlants> young(static_cast<std::size_t>(regenerationX_) * regenerationY_);
  tbb::parallel_for(std::size_t{0}, p.size(), [&](std::size_t i) {
    if (p.height_m[i] >= kRegenerationHeight_m) return;
    YoungPlants& cell = young[regenerationCellOf(p.east_m[i], p.north_m[i])];
    std::atomic_ref count(cell.count);
    std::uint8_t place = count.load(std::memory_order_relaxed);
    while (place < kYoungPlantsPerCell &&
           !count.compare_exchange_weak(place, static_cast<std::uint8_t>(place + 1),
                                        std::memory_order_relaxed)) {
    }
    if (place < kYoungPlantsPerCell) cell.species[place] = p.species[i];
    // Planted stock may stand closer than a cell: a full cell is closed however many it holds.
    if (p.height_m[i] >= kBreastHeight_m || place >= kYoungPlantsPerCell)
      std::atomic_ref(cell.closed).store(true, std::memory_order_relaxed);
  });
  const double cellArea = kRegenerationCell_m * kRegenerationCell_m;
  struct Newcomer {
    int species;
    double east, north;
  };
  // The cells' centres share their east down each column of cells and their north along
  // each row, and so their columns of the terrain's, the light's and the seeds' grids.
  std::vector<double> easts(regenerationX_), norths(regenerationY_);
  std::vector<int> terrainXs(regenerationX_), lightXs(regenerationX_);
  for (int x = 0; x < regenerationX_; ++x) {
    easts[x] = regenerationCentre(x, 0).x;
    terrainXs[x] = g.columnAt(easts[x]);
    lightXs[x] = light_.columnXAt(easts[x]);
  }
  for (int y = 0; y < regenerationY_; ++y) norths[y] = regenerationCentre(0, y).y;
  const SeedMap::Lattice seedCells = seeds_.latticeOf(easts, norths);
  std::vector<std::vector<Newcomer>> rows(regenerationY_);
  tbb::parallel_for(0, regenerationY_, [&](int y) {
    const int terrainY = g.rowAt(norths[y]);
    const long lightRow = static_cast<long>(light_.columnYAt(norths[y])) * light_.columnsX();
    // The light and the species' responses to it hold over a light column, which spans
    // several cells of the row: they are worked out once a column.
    long lightColumn = -1;
    double ground = 0.0, sky = 0.0;
    std::vector<double> response(species_.size());
    for (int x = 0; x < regenerationX_; ++x) {
      const std::size_t index = static_cast<std::size_t>(y) * regenerationX_ + x;
      YoungPlants cell = young[index];
      if (cell.closed || cell.count >= kYoungPlantsPerCell ||
          (!openCell_.empty() && openCell_[index]))
        continue;
      const double east = easts[x], north = norths[y];
      if (terrainXs[x] < 0 || terrainY < 0) continue;  // off the terrain's grid
      const std::size_t terrainCell = g.index(terrainXs[x], terrainY);
      if (terrain_.isOutside(terrainCell)) continue;
      if (const long column = lightRow + lightXs[x]; column != lightColumn) {
        lightColumn = column;
        ground = light_.groundLightInColumn(column);
        sky = light_.skyLightInColumn(column);
        for (std::size_t s = 0; s < species_.size(); ++s)
          response[s] = std::clamp(species_[s].ecology.lightResponse(ground), 0.0, 1.0);
      }
      const double groundLight = sky > 0.0 ? ground / sky : 1.0;  // relative to the open
      const Seedbed seedbed =
          seedbedAt(groundLight, moisture_[terrainCell], slope_deg_[terrainCell]);
      // Each species the cell lacks arrives on its own, as a Poisson number of seedlings of
      // which the cell takes one (iLand's establishment, species by species).
      Rng rng(streamKey(settings_.seed, state_.year, index, purpose("establishment")));
      for (std::size_t s = 0; s < species_.size() && cell.count < kYoungPlantsPerCell; ++s) {
        if (cell.holds(s)) continue;
        const EcosystemSpecies& sp = species_[s];
        const LifeHistory& life = sp.ecology.life;
        const double seeds =
            (seeds_.density(static_cast<int>(s), seedCells, x, y) + sp.seedRainPerHaPerYear / 1e4) *
            cellArea;
        const double expected = seeds * life.germination * sp.suitability[terrainCell] *
                                response[s] * seedbedEstablishment(life, seedbed);
        if (expected <= 0.0) continue;
        // A seedling arrives with chance 1 - exp(-expected), which is below `expected`: a
        // draw at or above that settles it without the exponential, as it does in most
        // cells, which expect far less than a seedling.
        const double draw = rng.uniform();
        if (draw >= expected || draw >= -std::expm1(-expected)) continue;
        cell.species[cell.count++] = static_cast<std::uint8_t>(s);
        const Newcomer seedling{static_cast<int>(s),
                                east + (rng.uniform() - 0.5) * kRegenerationCell_m,
                                north + (rng.uniform() - 0.5) * kRegenerationCell_m};
        // The cell's centre lies on the map and outside every open area; the seedling's own
        // spot may not.
        if (g.cellAt(static_cast<float>(seedling.east), static_cast<float>(seedling.north)) >= 0 &&
            !isKeptOpen({seedling.east, seedling.north}))
          rows[y].push_back(seedling);
      }
    }
  });
  // The seedlings join the plants row by row, numbered in that order: the rows are made
  // side by side into their places (a landscape's year brings millions).
  std::vector<std::size_t> rowStart(rows.size() + 1, 0);
  for (std::size_t y = 0; y < rows.size(); ++y) {
    rowStart[y + 1] = rowStart[y] + rows[y].size();
    for (const Newcomer& n : rows[y]) ++born_[n.species];
  }
  const std::size_t first = p.size();
  const std::uint64_t firstId = state_.nextId;
  state_.plants.resize(first + rowStart.back());
  state_.nextId += rowStart.back();
  tbb::parallel_for(std::size_t{0}, rows.size(), [&](std::size_t y) {
    for (std::size_t k = 0; k < rows[y].size(); ++k) {
      const Newcomer& n = rows[y][k];
      setSeedling(first + rowStart[y] + k, firstId + rowStart[y] + k, n.species, n.east, n.north);
    }
  });
}

void Ecosystem::step() {
  ++state_.year;
  std::fill(born_.begin(), born_.end(), 0);
  std::fill(died_.begin(), died_.end(), 0);
  std::fill(plantedDied_.begin(), plantedDied_.end(), 0);
  computeLight();
  grow();
  produceSeeds();
  applyMortality();
  establish();
  settleNewcomers();
}

}  // namespace eco
