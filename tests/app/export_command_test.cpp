// Runs `ecoforest export` as a user would.
#include <fstream>

#include <gtest/gtest.h>

#include "app_support.hpp"

namespace {

using eco::test::CommandResult;
using eco::test::ecoforest;
using eco::test::shortDefaultRun;

std::size_t treeRows(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) lines += !line.empty();
  return lines - 1;  // the header
}

TEST(ExportCommand, WritesAValidGltfWithOneInstancePerLivingTree) {
  const auto dir = eco::test::freshDirectory("app_export");
  for (const char* name : {"forest.glb", "forest.gltf"}) {
    const auto out = dir / name;
    CommandResult r =
        ecoforest("export " + shortDefaultRun().string() + " --year 10 --out " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::size_t trees = treeRows(shortDefaultRun() / "trees" / "year_0010.csv");
    EXPECT_GT(trees, 0u);
    EXPECT_NE(r.output.find("year 10, " + std::to_string(trees) + " trees"), std::string::npos)
        << r.output;
    const auto validator = std::filesystem::path(ECOFOREST_SOURCE_DIR) / "tools" / "gltf-validator";
    if (!std::filesystem::exists(validator / "node_modules" / "gltf-validator")) continue;
    CommandResult validated =
        eco::test::runCommand("node " + (validator / "validate.mjs").string() + " " + out.string());
    EXPECT_EQ(validated.exitCode, 0) << validated.output;
    EXPECT_NE(validated.output.find("\"errors\":0"), std::string::npos) << validated.output;
  }
}

TEST(ExportCommand, BadInputIsExitTwoAndWritesNothing) {
  const auto dir = eco::test::freshDirectory("app_export_bad");
  const std::string out = " --out " + (dir / "f.glb").string();
  CommandResult missing = ecoforest("export " + (dir / "nothing").string() + out);
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("no such run folder"), std::string::npos) << missing.output;
  CommandResult year = ecoforest("export " + shortDefaultRun().string() + " --year 3" + out);
  EXPECT_EQ(year.exitCode, 2);
  EXPECT_NE(year.output.find("has: 10, 20"), std::string::npos) << year.output;
  CommandResult format =
      ecoforest("export " + shortDefaultRun().string() + " --out " + (dir / "f.obj").string());
  EXPECT_EQ(format.exitCode, 2);
  CommandResult folder = ecoforest("export " + shortDefaultRun().string() + " --out " +
                                   (dir / "no" / "f.glb").string());
  EXPECT_EQ(folder.exitCode, 2);
  EXPECT_EQ(eco::test::entriesIn(dir), 0u);
}

}  // namespace
