// Runs `ecoforest compare` (and `run` with a plan) as a user would.
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <sstream>

#include "app_support.hpp"

namespace {

using eco::test::CommandResult;
using eco::test::ecoforest;

// A 170 m square of gentle hills for 30 years, afforested by `plan`.
std::filesystem::path scenarioWith(const std::string& name, const std::string& plan) {
  const auto dir = eco::test::freshDirectory(name);
  eco::test::writeFile(dir / "s.toml", fmt::format(R"(name = "{}"
seed = 4
[terrain]
cell_size_m = 10
[terrain.generate]
size = 17
relief_m = 20
base_altitude_m = 400
[simulation]
years = 30
[[species]]
file = "{}/species/beech.toml"
[[species]]
file = "{}/species/pine.toml"
[output]
dir = "{}"
snapshot_every_years = 10
{})",
                                                   name, ECOFOREST_DATA_DIR, ECOFOREST_DATA_DIR,
                                                   (dir / "run").string(), plan));
  return dir;
}

// The two runs made once for every test here: natural seeding from a forest west of the
// land, and a planted mix with a thinning.
const std::pair<std::filesystem::path, std::filesystem::path>& twoRuns() {
  static const auto runs = [] {
    const auto natural = scenarioWith("app_compare_natural", R"(
[[seed_source]]
species = { beech = 0.7, pine = 0.3 }
polygon = [[-300, -100], [-5, -100], [-5, 300], [-300, 300]]
)");
    const auto planted = scenarioWith("app_compare_planted", R"(
[[planting]]
species = { beech = 0.5, pine = 0.5 }
spacing_m = 2
[[thinning]]
method = "remove_species"
species = ["pine"]
from_year = 20
)");
    for (const auto& dir : {natural, planted}) {
      CommandResult r = ecoforest("run " + (dir / "s.toml").string());
      EXPECT_EQ(r.exitCode, 0) << r.output;
    }
    return std::pair{natural / "run", planted / "run"};
  }();
  return runs;
}

std::pair<int, int> sizeOf(const std::filesystem::path& png) {
  auto in = OIIO::ImageInput::open(png.string());
  if (!in) return {0, 0};
  return {in->spec().width, in->spec().height};
}

TEST(CompareCommand, WritesTheTableChartsAndStillsOfTheRuns) {
  const auto& [natural, planted] = twoRuns();
  const auto out = eco::test::freshDirectory("app_compare_out") / "cmp";
  CommandResult r =
      ecoforest(fmt::format("compare {} {} --out {} --years 10,30 --size 160x90 "
                            "--quality draft",
                            natural.string(), planted.string(), out.string()));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string csv = eco::test::readFile(out / "compare.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 2) << csv;
  EXPECT_NE(csv.find("\napp_compare_natural,10,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\napp_compare_planted,30,"), std::string::npos) << csv;
  // The planted run counts its 7,225 trees (a 170 m square at 2 m: 85 x 85) in every year.
  EXPECT_NE(csv.find(",7225,"), std::string::npos) << csv;
  EXPECT_NE(eco::test::readFile(out / "compare.md").find("## Year 30"), std::string::npos);
  for (const char* chart : {"basal_area.png", "stems_per_ha.png", "dominant_height.png",
                            "canopy_cover.png", "volume.png", "removed_volume.png"})
    EXPECT_EQ(sizeOf(out / chart), std::make_pair(900, 520)) << chart;
  for (const char* still : {"stills_year_0010.png", "stills_year_0030.png"})
    EXPECT_EQ(sizeOf(out / still), std::make_pair(2 * 160, 90 + 30)) << still;
  // The runs' stand tables of each year, and a chart of their diameter distributions.
  for (const char* chart : {"diameters_year_0010.png", "diameters_year_0030.png"})
    EXPECT_EQ(sizeOf(out / chart), std::make_pair(900, 520)) << chart;
  std::istringstream tables(eco::test::readFile(out / "stand_tables.csv"));
  std::string line;
  std::getline(tables, line);
  EXPECT_EQ(line.rfind("run,year,species,dbh_from_cm,dbh_to_cm,stems_per_ha", 0), 0u) << line;
  int planted30 = 0;
  while (std::getline(tables, line)) {
    EXPECT_TRUE(line.starts_with("app_compare_natural,") ||
                line.starts_with("app_compare_planted,"))
        << line;
    planted30 += line.starts_with("app_compare_planted,30,all,") ? 1 : 0;
  }
  EXPECT_GE(planted30, 1);  // its pines of 30 years pass 10 cm
  // Each run's species' and stand's measures in each year: 2 runs x 3 rows x 2 years.
  const std::string measures = eco::test::readFile(out / "stand_measures.csv");
  EXPECT_TRUE(measures.starts_with("run,year,species,stems_per_ha,basal_area_m2_per_ha,qmd_cm,"))
      << measures;
  EXPECT_EQ(std::count(measures.begin(), measures.end(), '\n'), 1 + 2 * 3 * 2) << measures;
}

// Within a region (the west half of the 170 m square): the stand tables and measures of the
// trees standing there, per hectare of its cells; the table and charts of stats.csv stay the
// whole map's.
TEST(CompareCommand, ComparesTheStandsWithinARegion) {
  const auto& [natural, planted] = twoRuns();
  const auto folder = eco::test::freshDirectory("app_compare_region");
  auto measuresOf = [&](const std::string& name, const std::string& region) {
    const auto out = folder / name;
    CommandResult r =
        ecoforest(fmt::format("compare {} {} --out {} --years 30 --no-stills {}", natural.string(),
                              planted.string(), out.string(), region));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return eco::test::readFile(out / "stand_measures.csv");
  };
  const std::string whole = measuresOf("whole", "");
  const std::string west =
      measuresOf("west", "--region 'polygon = [[-10, -10], [80, -10], [80, 170], [-10, 170]]'");
  EXPECT_EQ(std::count(west.begin(), west.end(), '\n'), 1 + 2 * 3) << west;
  EXPECT_NE(west, whole);  // the natural run's seeds come from the west: its west half differs
  CommandResult bad =
      ecoforest(fmt::format("compare {} {} --out {} --region 'polygon = [[0, 0]]'",
                            natural.string(), planted.string(), (folder / "bad").string()));
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("--region:1: polygon"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(folder / "bad"));
}

TEST(CompareCommand, BadArgumentsAreExitTwo) {
  const auto& [natural, planted] = twoRuns();
  const auto out = eco::test::freshDirectory("app_compare_bad") / "cmp";
  CommandResult one = ecoforest("compare " + natural.string() + " --out " + out.string());
  EXPECT_EQ(one.exitCode, 2);
  EXPECT_NE(one.output.find("at least two run folders"), std::string::npos) << one.output;
  CommandResult late = ecoforest(fmt::format("compare {} {} --out {} --years 40 --no-stills",
                                             natural.string(), planted.string(), out.string()));
  EXPECT_EQ(late.exitCode, 2);
  EXPECT_NE(late.output.find("has no year 40 (it has years 1 to 30)"), std::string::npos)
      << late.output;
  CommandResult missing = ecoforest(
      fmt::format("compare {} /nonexistent/run --out {}", natural.string(), out.string()));
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(out));  // refused before anything was written
}

TEST(PlanScenario, ABadPlanIsExitTwoAtItsLineAndRunWritesNothing) {
  const auto dir = scenarioWith("app_bad_plan", R"(
[[planting]]
species = { beech = 0.5, pine = 0.4 }
)");
  CommandResult shares = ecoforest("run " + (dir / "s.toml").string());
  EXPECT_EQ(shares.exitCode, 2);
  EXPECT_NE(shares.output.find("s.toml:20: planting[0].species: the shares sum to 0.9, not 1"),
            std::string::npos)
      << shares.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "run"));
  const auto mask = scenarioWith("app_bad_mask", R"(
[[exclusion]]
mask = "small.pgm"
)");
  eco::test::writeFile(mask / "small.pgm",
                       "P2\n4 4\n255\n0 0 0 0\n0 255 255 0\n0 255 255 0\n0 0 0 0\n");
  CommandResult size = ecoforest("run " + (mask / "s.toml").string());
  EXPECT_EQ(size.exitCode, 2);
  EXPECT_NE(size.output.find("s.toml:20: exclusion[0].mask: the mask"), std::string::npos)
      << size.output;
  EXPECT_NE(size.output.find("is 4 x 4 pixels; the terrain is 17 x 17 cells"), std::string::npos)
      << size.output;
  EXPECT_FALSE(std::filesystem::exists(mask / "run"));
}

}  // namespace
