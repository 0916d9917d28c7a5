#include "sim/plan/management.hpp"

#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "core/names.hpp"
#include "core/random.hpp"
#include "sim/ecology/stand_measures.hpp"
#include "sim/plan/layout.hpp"

namespace eco {
namespace {

std::vector<int> indicesOf(const std::vector<SpeciesShare>& shares,
                           const std::vector<EcosystemSpecies>& species) {
  std::vector<int> indices;
  for (const SpeciesShare& s : shares)
    indices.push_back(planSpeciesIndex(s.species, s.where, species));
  return indices;
}

// The species of a planting's tree at a spot: by its row's place in the pattern, or drawn by
// the mix's shares.
int speciesAt(const Planting& rule, const std::vector<int>& mix, const std::vector<int>& rows,
              const PlantingSpot& spot, Rng& rng) {
  if (!rows.empty()) {
    const int n = static_cast<int>(rows.size());
    return rows[((spot.row % n) + n) % n];
  }
  double pick = rng.uniform();
  for (std::size_t k = 0; k + 1 < mix.size(); ++k) {
    if (pick < rule.mix[k].share) return mix[k];
    pick -= rule.mix[k].share;
  }
  return mix.back();
}

}  // namespace

int planSpeciesIndex(const std::string& name, const SourceLocation& where,
                     const std::vector<EcosystemSpecies>& species) {
  const auto found = std::find_if(species.begin(), species.end(), [&](const EcosystemSpecies& s) {
    return s.species.isCalled(name);
  });
  if (found != species.end()) return static_cast<int>(found - species.begin());
  std::vector<std::string> names;
  for (const EcosystemSpecies& s : species) names.push_back(s.species.name);
  throw InputError(where, "no species '" + name + "' in the scenario" + didYouMean(name, names));
}

Management::Management(const Plan& plan, Ecosystem& ecosystem, std::uint64_t seed)
    : ecosystem_(ecosystem), seed_(seed) {
  const Grid& grid = ecosystem.grid();
  const std::vector<EcosystemSpecies>& species = ecosystem.species();
  for (const Planting& p : plan.planting)
    plantings_.push_back(
        {&p, Region(p.region, grid), indicesOf(p.mix, species), indicesOf(p.rows, species)});
  for (const Thinning& t : plan.thinning) {
    Region region(t.region, grid);
    const double area_ha = region.areaOnLandscape_m2(ecosystem.terrain()) / 1e4;
    std::vector<std::uint8_t> thinned(species.size(), t.species.empty() ? 1 : 0);
    for (const std::string& name : t.species) thinned[planSpeciesIndex(name, t.where, species)] = 1;
    thinnings_.push_back({&t, std::move(region), area_ha, std::move(thinned)});
  }
  for (const Exclusion& e : plan.exclusions) exclusions_.emplace_back(e.region, grid);
  if (!exclusions_.empty()) {
    // The ecosystem keeps its own copy: it may be stepped after this is gone.
    auto open = std::make_shared<const std::vector<Region>>(exclusions_);
    ecosystem.keepOpen([open](glm::dvec2 p) {
      return std::any_of(open->begin(), open->end(),
                         [&](const Region& r) { return r.contains(p); });
    });
  }
  for (const SeedSource& s : plan.seedSources) {
    Region region(s.region, grid, true);
    std::vector<double> shares(species.size(), 0.0);
    const std::vector<int> indices = indicesOf(s.mix, species);
    for (std::size_t k = 0; k < indices.size(); ++k) shares[indices[k]] += s.mix[k].share;
    if (!ecosystem.addSeedSource([&region](glm::dvec2 p) { return region.contains(p); }, s.cover,
                                 std::move(shares)))
      throw InputError(s.region.where,
                       "the seed source lies farther from the map than its seeds fly (five "
                       "kernel means): it would send none");
    seedSources_.push_back(std::move(region));
  }
}

void Management::plantAtStartOf(int year, PlanYear& done,
                                const std::function<void(const std::string&)>& warn) {
  const std::vector<EcosystemSpecies>& species = ecosystem_.species();
  for (std::size_t k = 0; k < plantings_.size(); ++k) {
    const PlacedPlanting& placed = plantings_[k];
    const Planting& rule = *placed.rule;
    if (rule.year != year) continue;
    const PlantingLayoutResult layout = layoutPlanting(
        rule, placed.region, ecosystem_.terrain(), streamKey(seed_, k, purpose("planting layout")));
    std::vector<std::int64_t> ruledOut(species.size(), 0), planted(species.size(), 0);
    std::int64_t keptOpen = 0;
    for (std::size_t i = 0; i < layout.spots.size(); ++i) {
      const PlantingSpot& spot = layout.spots[i];
      if (ecosystem_.isKeptOpen(spot.position)) {
        ++keptOpen;
        continue;
      }
      Rng rng(streamKey(seed_, k, i, purpose("planting mix")));
      const int s = speciesAt(rule, placed.mix, placed.rows, spot, rng);
      const long cell = ecosystem_.grid().cellAt(spot.position.x, spot.position.y);
      const bool possible = species[s].suitability[static_cast<std::size_t>(cell)] > 0.0f;
      if (!possible) ++ruledOut[s];
      ++planted[s];
      ecosystem_.plantSapling(
          s, spot.position.x, spot.position.y, rule.height_m, rule.stockAge_years,
          possible || !rule.survivalCheck ? PlantOrigin::Planted : PlantOrigin::PlantedRuledOut);
    }
    for (std::size_t s = 0; s < species.size(); ++s) done.planted[s] += planted[s];
    if (!warn) continue;
    const std::string at = fmt::format("{}:{}: planting", rule.where.file, rule.where.line);
    if (!layout.note.empty()) warn(at + ": " + layout.note);
    if (layout.spots.empty())
      warn(at + ": no spot of its layout lies in its region on the landscape; nothing is planted");
    if (keptOpen > 0)
      warn(fmt::format("{}: {} of its {} spots lie in areas kept open and stay unplanted", at,
                       keptOpen, layout.spots.size()));
    for (std::size_t s = 0; s < species.size(); ++s)
      if (ruledOut[s] > 0)
        warn(fmt::format("{}: {} of {} planted {} stand where a condition rules {} out{}", at,
                         ruledOut[s], planted[s], species[s].species.name, species[s].species.name,
                         rule.survivalCheck
                             ? "; they die in their first year (stats.csv: died_after_planting)"
                             : "; without survival_check they take their chances"));
  }
}

void Management::thinAtEndOf(int year, PlanYear& done) {
  const std::vector<EcosystemSpecies>& species = ecosystem_.species();
  for (const PlacedThinning& t : thinnings_) {
    if (!t.rule->appliesIn(year)) continue;
    const Plants& p = ecosystem_.plants();
    std::vector<std::uint8_t> removed(p.size(), 0);
    std::vector<std::size_t> candidates;
    // What a tree adds to the region's measure: a stem, or its basal area (m2).
    const bool byStems = t.rule->targetStemsPerHa.has_value();
    auto share = [&](std::size_t i) { return byStems ? 1.0 : basalAreaOf(p.dbh_m[i]); };
    double measure = 0.0;  // of the region's trees of at least 10 cm
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!t.region.contains({p.east_m[i], p.north_m[i]})) continue;
      if (t.rule->method == ThinningMethod::RemoveSpecies) {
        if (t.thinned[p.species[i]]) removed[i] = 1;
        continue;
      }
      if (p.dbh_m[i] < kMeasuredDbh_m) continue;
      measure += share(i);
      if (t.thinned[p.species[i]]) candidates.push_back(i);
    }
    if (t.rule->method != ThinningMethod::RemoveSpecies && t.area_ha > 0.0) {
      // Smallest (or largest) first; ties in the order of birth (the plants are in order of
      // place).
      const bool fromBelow = t.rule->method == ThinningMethod::FromBelow;
      std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
        if (p.dbh_m[a] != p.dbh_m[b])
          return fromBelow ? p.dbh_m[a] < p.dbh_m[b] : p.dbh_m[a] > p.dbh_m[b];
        return p.id[a] < p.id[b];
      });
      const double target =
          (byStems ? *t.rule->targetStemsPerHa : *t.rule->targetBasalArea_m2PerHa) * t.area_ha;
      for (std::size_t i : candidates) {
        if (measure <= target) break;
        removed[i] = 1;
        measure -= share(i);
      }
    }
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!removed[i]) continue;
      ++done.removed[p.species[i]];
      StandTally tally;
      tally.add(p.dbh_m[i], p.height_m[i], species[p.species[i]].ecology.life.formFactor);
      done.removedVolume_m3[p.species[i]] += tally.volume_m3;
      done.removedPlants.appendRow(p, i);
    }
    ecosystem_.removePlants(removed);
  }
}

Field Management::planMap() const {
  const Grid& g = ecosystem_.grid();
  Field map(g.cellCount(), 0.0f);
  auto mark = [&](const Region& region, PlanMapCode code) {
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x)
        if (region.contains({g.eastOf(x), g.northOf(y)}))
          map[g.index(x, y)] = static_cast<float>(code);
  };
  // In the codes' order, so that the later wins where rules overlap.
  for (const Region& r : seedSources_) mark(r, PlanMapCode::SeedSource);
  for (const PlacedThinning& t : thinnings_) mark(t.region, PlanMapCode::Thinned);
  for (const PlacedPlanting& p : plantings_) mark(p.region, PlanMapCode::Planted);
  for (const Region& r : exclusions_) mark(r, PlanMapCode::KeptOpen);
  return map;
}

}  // namespace eco
