#include "sim/run/stand_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/random.hpp"
#include "sim/ecology/stand_measures.hpp"
#include "sim/image_io.hpp"
#include "sim/run/run_format.hpp"
#include "sim/run/simulation.hpp"
#include "test_files.hpp"
#include "test_scenarios.hpp"

namespace eco {
namespace {

TreeRow tree(int species, float dbh_m, float height_m) {
  TreeRow row;
  row.species = species;
  row.dbh_m = dbh_m;
  row.height_m = height_m;
  return row;
}

double basalArea(float dbh_m) {
  const double d = dbh_m;
  return std::numbers::pi / 4.0 * d * d;
}

TEST(StandTable, TalliesEachTreeOfTenCentimetresIntoItsDiameterClass) {
  TreeSnapshot snapshot{150, {"beech", "pine"}, {}};
  snapshot.trees = {tree(0, 0.12f, 15.0f), tree(0, 0.14f, 17.0f), tree(1, 0.31f, 25.0f),
                    tree(0, 0.05f, 6.0f),    // under the calipering limit: not tallied
                    tree(0, 0.15f, 20.0f)};  // on a boundary: the class it opens
  const StandTable table = standTable(snapshot, {0.5, 0.4}, 2.0, 5.0);
  ASSERT_EQ(table.rows, (std::vector<std::string>{"beech", "pine", "all"}));
  ASSERT_EQ(table.classCount(), 5u);  // 10-15 up to 30-35, the thickest tree's
  EXPECT_DOUBLE_EQ(table.from_cm(0), 10.0);
  EXPECT_DOUBLE_EQ(table.from_cm(4), 30.0);

  const DiameterClass& thinBeech = table.classes[0][0];
  EXPECT_DOUBLE_EQ(thinBeech.stemsPerHa, 1.0);  // two trees on 2 ha
  EXPECT_NEAR(thinBeech.basalArea_m2PerHa, (basalArea(0.12f) + basalArea(0.14f)) / 2.0, 1e-12);
  EXPECT_NEAR(thinBeech.volume_m3PerHa,
              0.5 * (basalArea(0.12f) * 15.0 + basalArea(0.14f) * 17.0) / 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(thinBeech.meanHeight_m, 16.0);
  EXPECT_NEAR(thinBeech.meanSlenderness, (15.0 / double(0.12f) + 17.0 / double(0.14f)) / 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(table.classes[0][1].stemsPerHa, 0.5);
  EXPECT_DOUBLE_EQ(table.classes[0][1].meanHeight_m, 20.0);
  // Classes without trees are zeros, means included.
  EXPECT_EQ(table.classes[0][4].stemsPerHa, 0.0);
  EXPECT_EQ(table.classes[0][4].meanHeight_m, 0.0);
  EXPECT_EQ(table.classes[1][0].stemsPerHa, 0.0);
  EXPECT_DOUBLE_EQ(table.classes[1][4].stemsPerHa, 0.5);
  EXPECT_NEAR(table.classes[1][4].volume_m3PerHa, 0.4 * basalArea(0.31f) * 25.0 / 2.0, 1e-12);
  // Each row's measures: the beeches' quadratic mean diameter and Reineke's index by hand.
  const double beechQmd_cm =
      100.0 * std::sqrt((std::pow(double(0.12f), 2) + std::pow(double(0.14f), 2) +
                         std::pow(double(0.15f), 2)) /
                        3.0);
  EXPECT_NEAR(table.measures[0].qmd_cm, beechQmd_cm, 1e-9);
  EXPECT_NEAR(table.measures[0].sdi, 1.5 * std::pow(beechQmd_cm / 25.4, 1.605), 1e-9);
  EXPECT_DOUBLE_EQ(table.measures[2].stemsPerHa, 2.0);  // four trees on 2 ha
  // The stand's row holds every species'.
  EXPECT_DOUBLE_EQ(table.classes[2][0].stemsPerHa, 1.0);
  EXPECT_DOUBLE_EQ(table.classes[2][4].stemsPerHa, 0.5);
  const DiameterClass all = table.total(2);
  EXPECT_DOUBLE_EQ(all.stemsPerHa, 2.0);
  EXPECT_NEAR(all.meanHeight_m, (15.0 + 17.0 + 25.0 + 20.0) / 4.0, 1e-12);
}

TEST(StandTable, ItsClassesAddUpToTheStandMeasuresOfStatsCsv) {
  Rng random(7);
  TreeSnapshot snapshot{60, {"beech", "maple", "pine"}, {}};
  const std::vector<double> formFactors{0.5, 0.45, 0.42};
  for (int i = 0; i < 5000; ++i) {
    const float dbh = static_cast<float>(0.01 + 0.8 * std::pow(random.uniform(), 2.0));
    snapshot.trees.push_back(tree(i % 3, dbh, static_cast<float>(1.3 + 60.0 * dbh)));
  }
  for (const double width : {2.0, 5.0, 10.0}) {
    const StandTable table = standTable(snapshot, formFactors, 3.5, width);
    std::vector<StandTally> tallies(4);
    for (const TreeRow& t : snapshot.trees) {
      tallies[static_cast<std::size_t>(t.species)].add(t.dbh_m, t.height_m, formFactors[t.species]);
      tallies[3].add(t.dbh_m, t.height_m, formFactors[t.species]);
    }
    for (std::size_t row = 0; row < 4; ++row) {
      const StandMeasures expected = tallies[row].perHectare(3.5);
      const DiameterClass total = table.total(row);
      EXPECT_NEAR(total.stemsPerHa, expected.stemsPerHa, 1e-9) << width << " cm, row " << row;
      EXPECT_NEAR(total.basalArea_m2PerHa, expected.basalArea_m2PerHa, 1e-9);
      EXPECT_NEAR(total.volume_m3PerHa, expected.volume_m3PerHa, 1e-9);
    }
    // Every class holds the trees its bounds say.
    for (std::size_t k = 0; k < table.classCount(); ++k) {
      double stems = 0.0;
      for (const TreeRow& t : snapshot.trees)
        if (t.dbh_m >= kMeasuredDbh_m && 100.0 * t.dbh_m >= table.from_cm(k) &&
            100.0 * t.dbh_m < table.from_cm(k + 1))
          stems += 1.0;
      EXPECT_NEAR(table.classes[3][k].stemsPerHa * 3.5, stems, 1e-9) << width << " cm, class " << k;
    }
  }
}

TEST(StandTable, AStandWithoutTreesOfTenCentimetresHasNoClasses) {
  TreeSnapshot snapshot{5, {"beech"}, {tree(0, 0.02f, 2.0f)}};
  const StandTable table = standTable(snapshot, {0.5}, 1.0, 5.0);
  EXPECT_EQ(table.classCount(), 0u);
  EXPECT_EQ(table.total(1).stemsPerHa, 0.0);
  EXPECT_EQ(standTableCsv({table}).find('\n') + 1, standTableCsv({table}).size());  // the header
  EXPECT_NE(standTableText(table).find("total"), std::string::npos);
}

TEST(StandTable, WritesALinePerRowAndClassAndATableForReading) {
  TreeSnapshot snapshot{150, {"beech", "pine"}, {tree(0, 0.12f, 15.0f), tree(1, 0.31f, 25.0f)}};
  const StandTable table = standTable(snapshot, {0.5, 0.4}, 2.0, 10.0);
  std::istringstream csv(standTableCsv({table}));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "year,species,dbh_from_cm,dbh_to_cm,stems_per_ha,basal_area_m2_per_ha,volume_m3_per_ha,"
            "mean_height_m,mean_slenderness");
  std::vector<std::string> lines;
  while (std::getline(csv, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 9u);  // beech, pine and all, each in 10-20, 20-30 and 30-40
  EXPECT_EQ(lines[0].rfind("150,beech,10,20,0.50,", 0), 0u) << lines[0];
  EXPECT_EQ(lines[8].rfind("150,all,30,40,0.50,", 0), 0u) << lines[8];
  const std::string text = standTableText(table);
  EXPECT_NE(text.find("year 150, 2.00 ha"), std::string::npos) << text;
  EXPECT_NE(text.find("30-40"), std::string::npos) << text;
  EXPECT_NE(text.find("total"), std::string::npos) << text;
  // The measures: a line per row, the stand's last (two trees on 2 ha: 1 stem a hectare).
  EXPECT_EQ(standMeasuresCsvLines(table, "r,"),
            fmt::format("r,150,beech,0.50,{:.4f},12.00,{:.1f},{:.3f}\n"
                        "r,150,pine,0.50,{:.4f},31.00,{:.1f},{:.3f}\n"
                        "r,150,all,1.00,{:.4f},{:.2f},{:.1f},{:.3f}\n",
                        table.measures[0].basalArea_m2PerHa, table.measures[0].sdi,
                        table.measures[0].volume_m3PerHa, table.measures[1].basalArea_m2PerHa,
                        table.measures[1].sdi, table.measures[1].volume_m3PerHa,
                        table.measures[2].basalArea_m2PerHa, table.measures[2].qmd_cm,
                        table.measures[2].sdi, table.measures[2].volume_m3PerHa));
}

// The planted plot (test_scenarios.hpp) grown once for the tests of a run here.
const std::filesystem::path& plotRun() {
  static const std::filesystem::path run = [] {
    const auto folder = test::freshDirectory("stand_table_run");
    test::writeFile(folder / "s.toml", test::plantedPlotScenario(ECOFOREST_DATA_DIR));
    RunOptions options;
    options.scenarioFile = folder / "s.toml";
    options.out = folder / "run";
    runSimulation(options);
    return folder / "run";
  }();
  return run;
}

// A run's own snapshot, per hectare of its map, with its species' form factors: the totals
// are its stats.csv's (to the digits stats.csv prints; binary snapshots keep the diameters).
TEST(StandTable, OfARunAddsUpToItsStatsCsv) {
  const RunFolder run = openRunFolder(plotRun());
  const StandTable table = standTablesOfRun(run, {40}, 5.0).at(0);
  EXPECT_NEAR(table.area_ha, 45.0 * 45.0 / 1e4, 1e-12);
  const StatsFile stats = readStatsCsv(plotRun() / "stats.csv");
  ASSERT_EQ(table.rows.size(), stats.species.size() + 1);
  for (const StatsRow& row : stats.rows) {
    if (row.year != 40) continue;
    const std::size_t r =
        row.species == kAllSpecies
            ? table.rows.size() - 1
            : static_cast<std::size_t>(
                  std::find(table.rows.begin(), table.rows.end(),
                            stats.species[static_cast<std::size_t>(row.species)]) -
                  table.rows.begin());
    ASSERT_LT(r, table.rows.size());
    const DiameterClass total = table.total(r);
    EXPECT_NEAR(total.stemsPerHa, row.stemsPerHa, 0.05) << table.rows[r];
    EXPECT_NEAR(total.basalArea_m2PerHa, row.basalArea_m2PerHa, 5e-5) << table.rows[r];
    EXPECT_NEAR(total.volume_m3PerHa, row.volume_m3PerHa, 5e-3) << table.rows[r];
    EXPECT_NEAR(table.measures[r].qmd_cm, row.qmd_cm, 5e-3) << table.rows[r];
    EXPECT_NEAR(table.measures[r].sdi, row.sdi, 0.05) << table.rows[r];
  }
  EXPECT_GT(table.total(table.rows.size() - 1).stemsPerHa, 100.0);  // the pines pass 10 cm
  // Every year's rows are the scenario's species in its order, with or without trees.
  for (const StandTable& year : standTablesOfRun(run, {20, 40}, 5.0))
    EXPECT_EQ(year.rows, (std::vector<std::string>{"pine", "beech", "all"})) << year.year;
  EXPECT_THROW(standTablesOfRun(run, {40, 30}, 5.0), InputError);  // no snapshot of year 30
}

// Within a region: its trees per hectare of its cells. The map (9 x 9 cells of 5 m, -2.5 ..
// 42.5 m each way) cut at x = 17.5 m between cell centres: the two parts' trees add up to
// the map's, and each part's are the snapshot's trees on its side.
TEST(StandTable, WithinARegionTalliesItsTreesPerHectareOfItsCells) {
  const RunFolder run = openRunFolder(plotRun());
  auto regionOf = [](double west, double east) {
    RegionSpec region;
    region.kind = RegionSpec::Kind::Polygon;
    region.points = {{west, -10.0}, {east, -10.0}, {east, 50.0}, {west, 50.0}};
    return region;
  };
  const StandTable whole = standTablesOfRun(run, {40}, 5.0).at(0);
  const StandTable west = standTablesOfRun(run, {40}, 5.0, regionOf(-10.0, 17.5)).at(0);
  const StandTable east = standTablesOfRun(run, {40}, 5.0, regionOf(17.5, 50.0)).at(0);
  EXPECT_FALSE(whole.ofRegion);
  EXPECT_TRUE(west.ofRegion);
  EXPECT_NEAR(west.area_ha, 4 * 9 * 25.0 / 1e4, 1e-12);  // the cell centres x = 0 .. 15 m
  EXPECT_NEAR(east.area_ha, 5 * 9 * 25.0 / 1e4, 1e-12);
  const std::size_t all = whole.rows.size() - 1;
  double westStems = 0.0;
  for (const TreeRow& tree : readSnapshot(run, 40).trees)
    if (tree.dbh_m >= kMeasuredDbh_m && tree.east_m < 17.5) westStems += 1.0;
  EXPECT_GT(westStems, 10.0);
  EXPECT_NEAR(west.total(all).stemsPerHa * west.area_ha, westStems, 1e-9);
  for (auto measure : {&DiameterClass::stemsPerHa, &DiameterClass::basalArea_m2PerHa,
                       &DiameterClass::volume_m3PerHa})
    EXPECT_NEAR(west.total(all).*measure * west.area_ha + east.total(all).*measure * east.area_ha,
                whole.total(all).*measure * whole.area_ha, 1e-9);
  // The same cells as a mask (row 0 the north edge), the same table.
  std::vector<float> westColumns(9 * 9, 0.0f);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 4; ++x) westColumns[static_cast<std::size_t>(y * 9 + x)] = 1.0f;
  const auto maskFile = test::freshDirectory("stand_table_mask") / "west.exr";
  writeFloatImage(maskFile, 9, 9, 1, westColumns);
  RegionSpec mask;
  mask.kind = RegionSpec::Kind::Mask;
  mask.mask = maskFile;
  const StandTable masked = standTablesOfRun(run, {40}, 5.0, mask).at(0);
  EXPECT_EQ(masked.area_ha, west.area_ha);
  EXPECT_EQ(masked.total(all).stemsPerHa, west.total(all).stemsPerHa);
  EXPECT_EQ(masked.total(all).basalArea_m2PerHa, west.total(all).basalArea_m2PerHa);
  // A region off the map is refused at its key.
  RegionSpec off = regionOf(100.0, 200.0);
  off.where = SourceLocation("--region", 1, "polygon");
  try {
    standTablesOfRun(run, {40}, 5.0, off);
    ADD_FAILURE() << "a region off the map was tallied";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "polygon");
  }
}

}  // namespace
}  // namespace eco
