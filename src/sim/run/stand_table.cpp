#include "sim/run/stand_table.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "sim/ecology/ecosystem.hpp"
#include "sim/ecology/stand_measures.hpp"
#include "sim/plan/region.hpp"
#include "sim/run/run_format.hpp"
#include "sim/terrain.hpp"

namespace eco {
namespace {

constexpr double kFirstClass_cm = 100.0 * kMeasuredDbh_m;

// The sums a class is made of, before they are divided out.
struct ClassSums {
  double stems = 0.0, basalArea_m2 = 0.0, volume_m3 = 0.0, heights_m = 0.0, slenderness = 0.0;

  void add(const ClassSums& other) {
    stems += other.stems;
    basalArea_m2 += other.basalArea_m2;
    volume_m3 += other.volume_m3;
    heights_m += other.heights_m;
    slenderness += other.slenderness;
  }
  DiameterClass perHectare(double area_ha) const {
    DiameterClass c;
    if (stems == 0.0) return c;
    c.stemsPerHa = stems / area_ha;
    c.basalArea_m2PerHa = basalArea_m2 / area_ha;
    c.volume_m3PerHa = volume_m3 / area_ha;
    c.meanHeight_m = heights_m / stems;
    c.meanSlenderness = slenderness / stems;
    return c;
  }
};

// The snapshot's species numbered as the run's scenario numbers them, each of the
// scenario's species named even where none of its trees is there: tables of several years,
// and of runs of the same species, have the same rows in the same order.
void numberSpeciesAsScenario(TreeSnapshot& snapshot, const std::vector<EcosystemSpecies>& species,
                             const std::filesystem::path& snapshotFile) {
  std::vector<int> scenarioIndex;
  for (const std::string& name : snapshot.speciesNames) {
    auto it = std::find_if(species.begin(), species.end(),
                           [&](const EcosystemSpecies& s) { return s.species.name == name; });
    if (it == species.end())
      throw InputError(
          {snapshotFile, 0, "species"},
          fmt::format("species '{}' is not one of the run's scenario's species", name));
    scenarioIndex.push_back(static_cast<int>(it - species.begin()));
  }
  for (TreeRow& tree : snapshot.trees)
    tree.species = scenarioIndex[static_cast<std::size_t>(tree.species)];
  snapshot.speciesNames.clear();
  for (const EcosystemSpecies& s : species) snapshot.speciesNames.push_back(s.species.name);
}

}  // namespace

double StandTable::from_cm(std::size_t k) const {
  return kFirstClass_cm + classWidth_cm * static_cast<double>(k);
}

DiameterClass StandTable::total(std::size_t row) const {
  // Means of the whole row weight each class by its stems.
  ClassSums sums;
  for (const DiameterClass& c : classes[row]) {
    const double stems = c.stemsPerHa * area_ha;
    sums.add({stems, c.basalArea_m2PerHa * area_ha, c.volume_m3PerHa * area_ha,
              c.meanHeight_m * stems, c.meanSlenderness * stems});
  }
  return sums.perHectare(area_ha);
}

StandTable standTable(const TreeSnapshot& snapshot, const std::vector<double>& formFactors,
                      double area_ha, double classWidth_cm) {
  ECO_ASSERT(
      formFactors.size() == snapshot.speciesNames.size(),
      formFactors.size() << " form factors for " << snapshot.speciesNames.size() << " species");
  ECO_ASSERT(area_ha > 0.0 && classWidth_cm > 0.0,
             "area " << area_ha << " ha, classes of " << classWidth_cm << " cm");
  StandTable table;
  table.year = snapshot.year;
  table.area_ha = area_ha;
  table.classWidth_cm = classWidth_cm;
  table.rows = snapshot.speciesNames;
  table.rows.emplace_back(kAllSpeciesName);
  const std::size_t speciesCount = snapshot.speciesNames.size();

  // In the snapshot's order, so the sums do not depend on anything but the file.
  std::vector<std::vector<ClassSums>> sums(speciesCount);
  std::vector<StandTally> tallies(speciesCount + 1);  // each species', the stand's last
  for (const TreeRow& tree : snapshot.trees) {
    const double dbh_m = tree.dbh_m;
    if (dbh_m < kMeasuredDbh_m) continue;
    const double formFactor = formFactors[static_cast<std::size_t>(tree.species)];
    for (StandTally* tally : {&tallies[static_cast<std::size_t>(tree.species)], &tallies.back()})
      tally->add(dbh_m, tree.height_m, formFactor);
    const auto k =
        static_cast<std::size_t>(std::floor((100.0 * dbh_m - kFirstClass_cm) / classWidth_cm));
    std::vector<ClassSums>& row = sums[static_cast<std::size_t>(tree.species)];
    if (row.size() <= k) row.resize(k + 1);
    const double basalArea_m2 = basalAreaOf(dbh_m);
    row[k].add({1.0, basalArea_m2, formFactor * basalArea_m2 * tree.height_m, tree.height_m,
                tree.height_m / dbh_m});
  }
  std::size_t classCount = 0;
  for (const auto& row : sums) classCount = std::max(classCount, row.size());
  std::vector<ClassSums> stand(classCount);
  for (std::vector<ClassSums>& row : sums) {
    row.resize(classCount);
    for (std::size_t k = 0; k < classCount; ++k) stand[k].add(row[k]);
  }
  sums.push_back(std::move(stand));
  for (const std::vector<ClassSums>& row : sums) {
    std::vector<DiameterClass>& out = table.classes.emplace_back();
    for (const ClassSums& c : row) out.push_back(c.perHectare(area_ha));
  }
  for (const StandTally& tally : tallies) table.measures.push_back(tally.perHectare(area_ha));
  return table;
}

std::vector<StandTable> standTablesOfRun(const RunFolder& run, const std::vector<int>& years,
                                         double classWidth_cm,
                                         const std::optional<RegionSpec>& within) {
  for (int year : years) requireSnapshotYear(run, year);  // before the map and species
  std::vector<EcosystemSpecies> species;
  for (const ScenarioSpecies& entry : run.scenario.species)
    species.push_back(readEcosystemSpecies(entry.file, entry.where));
  const Terrain terrain = loadTerrain(run.scenario);
  std::optional<Region> region;
  if (within) region.emplace(*within, terrain.grid);
  const double area_ha =
      (region ? region->areaOnLandscape_m2(terrain) : terrain.grid.area_m2()) / 1e4;
  if (region && area_ha <= 0.0)
    throw InputError(within->where, "the region holds no cell centre of the landscape");
  // Only the trees a table counts are held: a landscape's snapshot has ten times as many
  // plants, most of them saplings.
  const TreeFilter counted = [&](const TreeRow& tree) {
    return tree.dbh_m >= kMeasuredDbh_m &&
           (!region || region->contains({tree.east_m, tree.north_m}));
  };
  std::vector<double> formFactors;
  for (const EcosystemSpecies& s : species) formFactors.push_back(s.ecology.life.formFactor);
  std::vector<StandTable> tables;
  for (int year : years) {
    TreeSnapshot snapshot = readSnapshot(run, year, counted);
    numberSpeciesAsScenario(snapshot, species, RunPaths{run.dir}.existingSnapshot(year));
    StandTable& table =
        tables.emplace_back(standTable(snapshot, formFactors, area_ha, classWidth_cm));
    table.ofRegion = region.has_value();
  }
  return tables;
}

std::string standTableCsv(const std::vector<StandTable>& tables) {
  std::string csv = std::string(kStandTableCsvHeader) + "\n";
  for (const StandTable& table : tables) csv += standTableCsvLines(table);
  return csv;
}

std::string standTableCsvLines(const StandTable& table, std::string_view prefix) {
  std::string text;
  for (std::size_t r = 0; r < table.rows.size(); ++r)
    for (std::size_t k = 0; k < table.classCount(); ++k) {
      const DiameterClass& c = table.classes[r][k];
      text +=
          fmt::format("{}{},{},{:g},{:g},{:.2f},{:.4f},{:.3f},{:.2f},{:.1f}\n", prefix, table.year,
                      table.rows[r], table.from_cm(k), table.from_cm(k + 1), c.stemsPerHa,
                      c.basalArea_m2PerHa, c.volume_m3PerHa, c.meanHeight_m, c.meanSlenderness);
    }
  return text;
}

std::string standMeasuresCsvLines(const StandTable& table, std::string_view prefix) {
  std::string text;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const StandMeasures& m = table.measures[r];
    text += fmt::format("{}{},{},{:.2f},{:.4f},{:.2f},{:.1f},{:.3f}\n", prefix, table.year,
                        table.rows[r], m.stemsPerHa, m.basalArea_m2PerHa, m.qmd_cm, m.sdi,
                        m.volume_m3PerHa);
  }
  return text;
}

std::string standTableText(const StandTable& table) {
  const std::size_t species = table.rows.size() - 1;
  std::string text = fmt::format(
      "year {}, {:.2f} ha{}: trees of at least {:g} cm dbh in classes of {:g} cm, per hectare\n",
      table.year, table.area_ha, table.ofRegion ? " within the region" : "", kFirstClass_cm,
      table.classWidth_cm);
  std::vector<std::size_t> widths;
  for (std::size_t r = 0; r < species; ++r)
    widths.push_back(std::max<std::size_t>(8, table.rows[r].size()));
  auto line = [&](const std::string& label, auto&& speciesCell, const DiameterClass& stand) {
    text += fmt::format("{:<9}", label);
    for (std::size_t r = 0; r < species; ++r)
      text += fmt::format(" {:>{}}", speciesCell(r), widths[r]);
    text += fmt::format(" | {:>8.1f} {:>7.2f} {:>8.1f} {:>8.1f} {:>5.0f}\n", stand.stemsPerHa,
                        stand.basalArea_m2PerHa, stand.volume_m3PerHa, stand.meanHeight_m,
                        stand.meanSlenderness);
  };
  text += fmt::format("{:<9}", "dbh cm");
  for (std::size_t r = 0; r < species; ++r)
    text += fmt::format(" {:>{}}", table.rows[r], widths[r]);
  text += fmt::format(" | {:>8} {:>7} {:>8} {:>8} {:>5}\n", "stems", "m²/ha", "m³/ha", "height m",
                      "h/d");
  for (std::size_t k = 0; k < table.classCount(); ++k)
    line(
        fmt::format("{:g}-{:g}", table.from_cm(k), table.from_cm(k + 1)),
        [&](std::size_t r) { return fmt::format("{:.1f}", table.classes[r][k].stemsPerHa); },
        table.classes[species][k]);
  line(
      "total", [&](std::size_t r) { return fmt::format("{:.1f}", table.total(r).stemsPerHa); },
      table.total(species));
  // What a forester reports of each species and the stand (stats.csv's measures).
  text += fmt::format("\n{:<9} {:>8} {:>7} {:>7} {:>6} {:>8}\n", "", "stems", "m²/ha", "qmd cm",
                      "SDI", "m³/ha");
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const StandMeasures& m = table.measures[r];
    text += fmt::format("{:<9} {:>8.1f} {:>7.2f} {:>7.1f} {:>6.0f} {:>8.1f}\n", table.rows[r],
                        m.stemsPerHa, m.basalArea_m2PerHa, m.qmd_cm, m.sdi, m.volume_m3PerHa);
  }
  return text;
}

}  // namespace eco
