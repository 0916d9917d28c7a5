// Runs `ecoforest conditions` and `ecoforest terrain` as a user would.
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app_support.hpp"
#include "test_files.hpp"

namespace {

using RunResult = eco::test::CommandResult;

RunResult run(const std::string& arguments) {
  return eco::test::runCommand(std::string(ECOFOREST_EXE) + " " + arguments);
}

}  // namespace

TEST(ConditionsCommand, TheValleyScenarioWritesMapsAndSummary) {
  auto dir = eco::test::freshDirectory("app_conditions");
  RunResult r = run("conditions valley --out " + dir.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* field : {"altitude", "slope", "aspect", "moisture", "windiness", "sunniness"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "maps" / (std::string(field) + ".exr"))) << field;
    EXPECT_TRUE(std::filesystem::exists(dir / "maps" / (std::string(field) + ".png"))) << field;
  }
  nlohmann::json summary = nlohmann::json::parse(eco::test::readFile(dir / "conditions.json"));
  EXPECT_EQ(summary["scenario"], "valley");
  EXPECT_NEAR(summary["grid"]["area_km2"].get<double>(), 6.0, 0.1);  // the paper's 6 km2
  EXPECT_NEAR(summary["fields"]["altitude"]["min"].get<double>(), 260.0, 0.01);
  EXPECT_NEAR(summary["fields"]["altitude"]["max"].get<double>(), 910.0, 0.01);
  EXPECT_EQ(r.output.find('\r'), std::string::npos) << "no progress line when not on a terminal";
}

TEST(ConditionsCommand, SameOutputsWithOneAndTwoThreads) {
  auto one = eco::test::freshDirectory("app_threads1"),
       two = eco::test::freshDirectory("app_threads2");
  ASSERT_EQ(run("conditions valley --threads 1 --out " + one.string()).exitCode, 0);
  ASSERT_EQ(run("conditions valley --threads 2 --out " + two.string()).exitCode, 0);
  for (const char* field : {"moisture", "windiness", "sunniness"}) {
    std::string name = std::string(field) + ".exr";
    EXPECT_TRUE(eco::test::readFile(one / "maps" / name) ==
                eco::test::readFile(two / "maps" / name))
        << field;
  }
}

TEST(ConditionsCommand, BadInputIsExitTwoWithFileAndLine) {
  auto dir = eco::test::freshDirectory("app_conditions_bad");
  std::ofstream(dir / "zero.toml") << "[terrain]\nheightmap = \"h.png\"\ncell_size_m = 0\n";
  RunResult zero =
      run("conditions " + (dir / "zero.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(zero.exitCode, 2);
  EXPECT_NE(zero.output.find("zero.toml:3: terrain.cell_size_m"), std::string::npos) << zero.output;
  std::ofstream(dir / "missing.toml") << "[terrain]\nheightmap = \"nothere.png\"\n";
  RunResult missing =
      run("conditions " + (dir / "missing.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("nothere.png: no such file"), std::string::npos) << missing.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  EXPECT_EQ(run("conditions nowhere").exitCode, 2);
}

// A PNG whose header claims 65,535 x 65,535 pixels (the fuzz reproducer, without the byte
// that chooses the format): refused from its header, before 17 GB are allocated.
TEST(ConditionsCommand, AHeightmapClaimingHugeDimensionsIsRefusedAtOnce) {
  auto dir = eco::test::freshDirectory("app_conditions_huge");
  const std::string reproducer =
      eco::test::readFile(std::filesystem::path(ECOFOREST_SOURCE_DIR) /
                          "tests/fuzz/crashes/heightmap/png_claims_65535_squared");
  eco::test::writeFile(dir / "huge.png", reproducer.substr(1));
  std::ofstream(dir / "huge.toml") << "[terrain]\nheightmap = \"huge.png\"\ncell_size_m = 1\n";
  // Under a 4 GB address-space limit, as in the audit that found it (not under the
  // sanitizers, whose shadow memory alone reserves terabytes of address space).
  const std::string limit = ECOFOREST_SANITIZED ? "" : "ulimit -v 4000000; ";
  RunResult r =
      eco::test::runCommand(limit + std::string(ECOFOREST_EXE) + " conditions " +
                            (dir / "huge.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("the image is 65535 x 65535 pixels; ecoforest reads heightmaps of at "
                          "most 16384 x 16384 pixels"),
            std::string::npos)
      << r.output;
}

TEST(ConditionsCommand, AFullDiskOrAReadOnlyFolderIsAClearErrorAndLeavesNothing) {
  const auto confined = eco::test::inSmallFileSystem(
      std::string(ECOFOREST_EXE) + " conditions valley --out \"$SPACE/c\"", 200);
  ECO_SKIP_WITHOUT(confined);
  EXPECT_EQ(confined->result.exitCode, 3) << confined->result.output;
  EXPECT_NE(confined->result.output.find("No space left on device"), std::string::npos)
      << confined->result.output;
  EXPECT_FALSE(eco::test::holdsATemporary(confined->files)) << confined->files;
  // A read-only folder: the same clear error, and nothing written.
  const auto readOnly = eco::test::inSmallFileSystem(
      std::string(ECOFOREST_EXE) + " conditions valley --out \"$SPACE\"", 1000, "ro");
  ECO_SKIP_WITHOUT(readOnly);
  EXPECT_EQ(readOnly->result.exitCode, 3) << readOnly->result.output;
  EXPECT_NE(readOnly->result.output.find("Read-only file system"), std::string::npos);
  EXPECT_EQ(readOnly->files, "");
}

TEST(TerrainCommand, SavesAHeightmapTheConditionsCanRead) {
  auto dir = eco::test::freshDirectory("app_terrain");
  std::ofstream(dir / "gen.toml")
      << "seed = 3\n[terrain]\ncell_size_m = 10\n[terrain.generate]\nsize = 65\n"
         "relief_m = 300\nbase_altitude_m = 100\n";
  RunResult saved =
      run("terrain " + (dir / "gen.toml").string() + " --out " + (dir / "h.png").string());
  ASSERT_EQ(saved.exitCode, 0) << saved.output;
  EXPECT_NE(saved.output.find("height_range_m = [100.0, 400.0]"), std::string::npos)
      << saved.output;
  std::ofstream(dir / "read.toml")
      << "[terrain]\nheightmap = \"h.png\"\ncell_size_m = 10\nheight_range_m = [100, 400]\n";
  RunResult conditions =
      run("conditions " + (dir / "read.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(conditions.exitCode, 0) << conditions.output;
  nlohmann::json summary =
      nlohmann::json::parse(eco::test::readFile(dir / "out" / "conditions.json"));
  EXPECT_NEAR(summary["fields"]["altitude"]["max"].get<double>(), 400.0, 0.01);
}
