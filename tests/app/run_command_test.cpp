// Runs `ecoforest run` as a user would.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app_support.hpp"
#include "core/error.hpp"
#include "gdal_tools.hpp"
#include "sim/grid.hpp"
#include "sim/image_io.hpp"
#include "sim/run/run_format.hpp"
#include "test_files.hpp"

namespace {

using eco::test::CommandResult;

CommandResult run(const std::string& arguments) {
  return eco::test::runCommand(std::string(ECOFOREST_EXE) + " " + arguments);
}

int lastYearIn(const std::string& stats) {
  const std::size_t start = stats.rfind('\n', stats.size() - 2) + 1;
  return std::stoi(stats.substr(start));
}

TEST(RunCommand, TheDefaultScenarioWritesARunFolder) {
  const auto dir = eco::test::freshDirectory("app_run");
  CommandResult r = run("run --years 12 --out " + dir.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("default: 12 years"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("year 12/12:"), std::string::npos) << "plain progress lines";
  EXPECT_EQ(r.output.find('\r'), std::string::npos);
  const nlohmann::json json = nlohmann::json::parse(eco::test::readFile(dir / "run.json"));
  EXPECT_EQ(json["status"], "complete");
  EXPECT_EQ(json["last_year"], 12);
  EXPECT_EQ(json["scenario"]["name"], "default");
  EXPECT_TRUE(json["final_counts"].contains("beech"));
  EXPECT_TRUE(std::filesystem::exists(dir / "trees" / "year_0010.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "trees" / "year_0012.csv"));

  // --resume with more years continues the same run.
  // The memory check can be overridden (it passes here anyway: the flag is accepted).
  CommandResult more = run("run --resume --years 14 --ignore-memory-check --out " + dir.string());
  ASSERT_EQ(more.exitCode, 0) << more.output;
  EXPECT_EQ(lastYearIn(eco::test::readFile(dir / "stats.csv")), 14);
}

TEST(RunCommand, CtrlCStopsAfterAYearWithCompleteFiles) {
  const auto dir = eco::test::freshDirectory("app_run_interrupt");
  // One SIGINT, as Ctrl-C sends, once the first year is in stats.csv (a header and a row per
  // species and the stand). Not `timeout -s INT`: it signals the child and then its process
  // group, and a second signal that lands after the first was handled stops at once.
  const std::string stats = (dir / "stats.csv").string();
  CommandResult r =
      eco::test::interruptWhen("run --years 400 --out " + dir.string(),
                               "{ [ -f " + stats + " ] && [ $(wc -l < " + stats + ") -ge 2 ]; }");
  ASSERT_EQ(r.exitCode, 130) << r.output;
  EXPECT_NE(r.output.find("--resume"), std::string::npos) << r.output;
  const int stopped = lastYearIn(eco::test::readFile(dir / "stats.csv"));
  EXPECT_GT(stopped, 0);
  EXPECT_EQ(nlohmann::json::parse(eco::test::readFile(dir / "run.json"))["status"], "interrupted");
  CommandResult resumed =
      run("run --resume --years " + std::to_string(stopped + 1) + " --out " + dir.string());
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  EXPECT_EQ(lastYearIn(eco::test::readFile(dir / "stats.csv")), stopped + 1);
}

// A disk that fills during the run: a clear error, exit 3, run.json says the run failed, and
// no temporary is left.
TEST(RunCommand, AFullDiskFailsClearlyAndLeavesNoPartialFile) {
  const auto confined = eco::test::inSmallFileSystem(
      std::string(ECOFOREST_EXE) +
          " run --years 3 --out \"$SPACE/run\"; rc=$?; cat \"$SPACE/run/run.json\"; exit $rc",
      600);
  ECO_SKIP_WITHOUT(confined);
  EXPECT_EQ(confined->result.exitCode, eco::kExitEnvironment) << confined->result.output;
  EXPECT_NE(confined->result.output.find("No space left on device"), std::string::npos)
      << confined->result.output;
  EXPECT_NE(confined->result.output.find("\"status\": \"failed\""), std::string::npos)
      << confined->result.output;
  EXPECT_FALSE(eco::test::holdsATemporary(confined->files)) << confined->files;
}

TEST(RunCommand, AReadOnlyFolderIsAClearError) {
  const auto confined = eco::test::inSmallFileSystem(
      std::string(ECOFOREST_EXE) + " run --years 2 --out \"$SPACE\"", 1000, "ro");
  ECO_SKIP_WITHOUT(confined);
  EXPECT_EQ(confined->result.exitCode, eco::kExitEnvironment) << confined->result.output;
  EXPECT_NE(confined->result.output.find("Read-only file system"), std::string::npos)
      << confined->result.output;
  EXPECT_EQ(confined->files, "");
}

TEST(RunCommand, ASecondRunIntoTheSameFolderIsRefused) {
  const auto dir = eco::test::freshDirectory("app_run_twice");
  const std::string exe = ECOFOREST_EXE;
  // The first runs for long; the second starts once the first has claimed the folder.
  CommandResult r = eco::test::runCommand(
      "(" + exe + " run --years 400 --out " + dir.string() + " >/dev/null 2>&1 & first=$!\n" +
      "while [ ! -f " + (dir / "run.json").string() + " ]; do sleep 0.05; done\n" + exe +
      " run --years 2 --out " + dir.string() + "; rc=$?\nkill -INT $first; wait $first\nexit $rc)");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("another ecoforest run (process"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("is writing into this folder"), std::string::npos) << r.output;
}

// kill -9 at several points, each time resumed (or, before the first checkpoint, started
// afresh): the same files as a run never interrupted.
TEST(RunCommand, KilledAtSeveralPointsAndResumedGivesTheSameFiles) {
  const auto& whole = eco::test::shortDefaultRun();  // 20 years
  const auto dir = eco::test::freshDirectory("app_run_killed");
  const std::string exe = ECOFOREST_EXE;
  const std::string stats = (dir / "stats.csv").string();
  // Starts a run, waits until stats.csv has `rows` lines (4 a year: three species and the
  // stand) or run.json exists (rows 0), then kills it without warning.
  auto killAt = [&](int rows, const std::string& flags) {
    const std::string until = rows == 0 ? "[ -f " + (dir / "run.json").string() + " ]"
                                        : "[ -f " + stats + " ] && [ $(wc -l < " + stats +
                                              ") -ge " + std::to_string(rows) + " ]";
    return eco::test::runCommand(exe + " run --years 20 " + flags + " --out " + dir.string() +
                                 " >/dev/null 2>&1 & pid=$!\nuntil " + until +
                                 "; do sleep 0.02; done\nkill -9 $pid; wait $pid; exit 0");
  };
  killAt(0, "");
  ASSERT_EQ(eco::test::ecoforest("run --years 20 --out " + dir.string()).exitCode, 0);
  killAt(1 + 4 * 6, "");
  killAt(1 + 4 * 14, "--resume");
  CommandResult last = eco::test::ecoforest("run --years 20 --resume --out " + dir.string());
  ASSERT_EQ(last.exitCode, 0) << last.output;
  for (const char* file :
       {"stats.csv", "trees/year_0010.csv", "trees/year_0020.csv", "maps/canopy_height.exr"})
    EXPECT_TRUE(eco::test::readFile(whole / file) == eco::test::readFile(dir / file)) << file;
  EXPECT_EQ(nlohmann::json::parse(eco::test::readFile(dir / "run.json"))["status"], "complete");
}

TEST(RunCommand, BadInputIsExitTwo) {
  const auto dir = eco::test::freshDirectory("app_run_bad");
  CommandResult none = run("run --resume --out " + dir.string());
  EXPECT_EQ(none.exitCode, 2);
  EXPECT_NE(none.output.find("checkpoint.bin: cannot open the checkpoint"), std::string::npos)
      << none.output;
  eco::test::writeFile(dir / "bad.toml",
                       "name = \"bad\"\n[terrain.generate]\nsize = 17\n"
                       "[[species]]\nfile = \"nothere.toml\"\n");
  CommandResult missing =
      run("run " + (dir / "bad.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("bad.toml:5: species[0].file: species file not found"),
            std::string::npos)
      << missing.output;
  EXPECT_EQ(run("run --years 0").exitCode, 2);
}

// A GeoTIFF as a GIS writes it, 8 m pixels in ETRS89 / UTM 32N with -9999 as no-data in
// its north-west corner: the run uses 8 m cells, plants nothing on no-data, and every map
// and the exported trees are where the heightmap was, as GDAL reads them.
TEST(RunCommand, AGeoTiffHeightmapIsGeoreferencedFromInputToOutputs) {
  if (!eco::test::gdalInstalled())
    GTEST_SKIP() << "gdal-bin is not installed (scripts/test installs it)";
  const auto dir = eco::test::freshDirectory("app_run_geotiff");
  constexpr int kWidth = 48, kHeight = 40;
  constexpr double kWest = 612000.0, kNorth = 5230000.0;
  std::vector<float> heights(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      heights[y * kWidth + x] = x < 12 && y < 10 ? -9999.0f : 500.0f + 1.5f * x + 0.5f * y;
  eco::writeFloatImage(dir / "raw.tif", kWidth, kHeight, 1, heights);
  eco::test::gdalGeoreference(dir / "raw.tif", dir / "dem.tif", 25832, kWest, kNorth, 8.0, kWidth,
                              kHeight, -9999.0);
  const std::string species = std::string(ECOFOREST_DATA_DIR) + "/species/beech.toml";
  eco::test::writeFile(dir / "geo.toml",
                       "name = \"geo\"\n[terrain]\nheightmap = \"dem.tif\"\n"
                       "[[species]]\nfile = \"" +
                           species + "\"\nseed_rain_per_ha_per_year = 3000\n");
  const auto out = dir / "run";
  CommandResult r = run("run " + (dir / "geo.toml").string() + " --years 4 --out " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;

  const nlohmann::json conditions =
      nlohmann::json::parse(eco::test::readFile(out / "conditions.json"));
  EXPECT_EQ(conditions["grid"]["cell_dx_m"], 8.0);
  EXPECT_EQ(conditions["grid"]["epsg"], 25832);
  const eco::TreeSnapshot trees = eco::readTrees(out / "trees" / "year_0004.csv");
  ASSERT_GT(trees.trees.size(), 100u);
  const eco::Grid grid{kWidth, kHeight, 8.0, 8.0};
  for (const eco::TreeRow& tree : trees.trees) {
    // The snapshot keeps millimetres: a plant within half of one of the map's east or south
    // edge is written on it, which the grid counts as beyond. Look a millimetre inside.
    const long cell = grid.cellAt(tree.east_m - 1e-3, tree.north_m + 1e-3);
    ASSERT_GE(cell, 0);
    EXPECT_FALSE(cell % kWidth < 12 && cell / kWidth < 10) << "a tree on no-data: " << tree.id;
  }
  std::size_t maps = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out / "maps")) {
    const std::string name = entry.path().filename().string();
    if (name.ends_with("_legend.png") ||
        (entry.path().extension() != ".tif" && entry.path().extension() != ".png"))
      continue;
    SCOPED_TRACE(name);
    const nlohmann::json info = eco::test::gdalInfo(entry.path());
    EXPECT_EQ(info["geoTransform"], nlohmann::json::array({kWest, 8.0, 0.0, kNorth, 0.0, -8.0}));
    EXPECT_EQ(eco::test::gdalEpsg(info), 25832);
    ++maps;
  }
  EXPECT_EQ(maps, 2u * 8u);  // six conditions, a suitability and the canopy height

  CommandResult exported =
      run("export " + out.string() + " --out " + (dir / "trees.geojson").string());
  ASSERT_EQ(exported.exitCode, 0) << exported.output;
  EXPECT_NE(exported.output.find("EPSG:25832"), std::string::npos) << exported.output;
  CommandResult ogr = eco::test::runCommand("ogrinfo -ro -so " + (dir / "trees.geojson").string() +
                                            " trees_year_0004");
  EXPECT_NE(ogr.output.find(fmt::format("Feature Count: {}", trees.trees.size())),
            std::string::npos)
      << ogr.output;
  EXPECT_NE(ogr.output.find("ID[\"EPSG\",25832]"), std::string::npos) << ogr.output;

  // A cell size that disagrees with the file's pixels is refused where it is written.
  eco::test::writeFile(dir / "bad.toml",
                       "name = \"bad\"\n[terrain]\nheightmap = \"dem.tif\"\n"
                       "cell_size_m = 10\n[[species]]\nfile = \"" +
                           species + "\"\n");
  CommandResult bad =
      run("run " + (dir / "bad.toml").string() + " --years 1 --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("bad.toml:4: terrain.cell_size_m"), std::string::npos) << bad.output;
}

}  // namespace
