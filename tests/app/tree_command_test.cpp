// Runs the real `ecoforest` program as a user would.
#include <unistd.h>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"

namespace {

using RunResult = eco::test::CommandResult;

RunResult run(const std::string& arguments) {
  return eco::test::runCommand(std::string(ECOFOREST_EXE) + " " + arguments);
}

std::filesystem::path freshDirectory(const std::string& name) {
  return eco::test::freshDirectory("app_" + name);
}

nlohmann::json statsOf(const std::string& arguments) {
  RunResult r = run("tree " + arguments + " --stats");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return nlohmann::json::parse(r.output);
}

}  // namespace

TEST(TreeCommand, StatsForThePapersTrees) {
  nlohmann::json beech = statsOf("beech");
  EXPECT_EQ(beech["species"], "beech");
  EXPECT_EQ(beech["segments"], 1999);
  EXPECT_EQ(beech["terminal_segments"], 1000);
  EXPECT_EQ(beech["leaves"], 5000);
  EXPECT_NEAR(beech["trunk_diameter_m"].get<double>(), 0.01 * std::sqrt(1000.0), 1e-6);
  EXPECT_GT(beech["height_m"].get<double>(), 5.0);
  for (const char* key :
       {"strands", "max_gravelius", "max_weibull", "crown_radius_m", "build_ms", "seed"})
    EXPECT_TRUE(beech.contains(key)) << key;
  EXPECT_GT(beech["triangles"]["lod0"].get<int>(), beech["triangles"]["lod1"].get<int>());
  EXPECT_GT(beech["triangles"]["lod1"].get<int>(), beech["triangles"]["lod2"].get<int>());
  nlohmann::json pine = statsOf("pine");
  EXPECT_EQ(pine["segments"], 11999);
  EXPECT_EQ(pine["terminal_segments"], 6000);
}

TEST(TreeCommand, AgeAndSeedChangeTheTree) {
  EXPECT_LT(statsOf("maple --age 0.3")["height_m"].get<double>(),
            statsOf("maple --age 0.8")["height_m"].get<double>());
  EXPECT_NE(statsOf("maple --seed 1")["crown_radius_m"],
            statsOf("maple --seed 2")["crown_radius_m"]);
}

TEST(TreeCommand, SidesSetTheTubeResolution) {
  int coarse = statsOf("beech --sides 4")["triangles"]["lod0"].get<int>();
  int fine = statsOf("beech --sides 16")["triangles"]["lod0"].get<int>();
  EXPECT_GT(fine, coarse + 5000);
  EXPECT_EQ(run("tree beech --sides 2").exitCode, 2);
}

TEST(TreeCommand, WritesEveryFormat) {
  auto dir = freshDirectory("formats");
  for (const char* name : {"t.obj", "t.gltf", "t.glb", "t.pov", "t.wrl"}) {
    RunResult r = run("tree shrub --lod 1 --out " + (dir / name).string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GT(std::filesystem::file_size(dir / name), 1000u) << name;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "t.mtl"));
  EXPECT_TRUE(std::filesystem::exists(dir / "t_bark.png"));
}

TEST(TreeCommand, GltfPassesTheKhronosValidator) {
  const auto validator = std::filesystem::path(ECOFOREST_SOURCE_DIR) / "tools" / "gltf-validator";
  if (!std::filesystem::exists(validator / "node_modules" / "gltf-validator"))
    GTEST_SKIP() << "the glTF validator is not installed (scripts/setup installs it)";
  auto dir = freshDirectory("validator");
  for (std::string args : {"beech --lod 0", "pine --lod 1", "maple --lod 2", "shrub --age 0.4"}) {
    for (const char* extension : {".glb", ".gltf"}) {
      auto file = dir / ("tree" + std::string(extension));
      ASSERT_EQ(run("tree " + args + " --out " + file.string()).exitCode, 0);
      RunResult validated = eco::test::runCommand("node " + (validator / "validate.mjs").string() +
                                                  " " + file.string());
      const std::string& report = validated.output;
      EXPECT_EQ(validated.exitCode, 0) << args << extension << ": " << report;
      EXPECT_NE(report.find("\"errors\":0"), std::string::npos) << report;
    }
  }
}

TEST(TreeCommand, BadSpeciesFileIsExitTwoWithFileLineAndNoOutput) {
  auto dir = freshDirectory("bad");
  std::ifstream in(std::filesystem::path(ECOFOREST_DATA_DIR) / "species" / "beech.toml");
  std::string text((std::istreambuf_iterator<char>(in)), {});
  text.replace(text.find("kc = 0.3"), 8, "kc = \"strong\"");
  std::ofstream(dir / "bad.toml") << text;
  RunResult r = run("tree " + (dir / "bad.toml").string() + " --out " + (dir / "bad.glb").string());
  EXPECT_EQ(r.exitCode, 2);
  std::string expected = "ecoforest: error: " + (dir / "bad.toml").string() + ":";
  EXPECT_EQ(r.output.rfind(expected, 0), 0u) << r.output;
  EXPECT_NE(r.output.find("strand.kc: expected a number"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.glb"));
  EXPECT_EQ(eco::test::entriesIn(dir), 1u);  // no temporaries
}

TEST(TreeCommand, BadArgumentsAreExitTwo) {
  auto dir = freshDirectory("args");
  RunResult unknownSpecies = run("tree baobab");
  EXPECT_EQ(unknownSpecies.exitCode, 2);
  EXPECT_NE(unknownSpecies.output.find("ecoforest: error: baobab: unknown species"),
            std::string::npos);
  EXPECT_EQ(run("tree beech --age 1.5").exitCode, 2);
  EXPECT_EQ(run("tree beech --lod 3").exitCode, 2);
  EXPECT_EQ(run("tree").exitCode, 2);
  EXPECT_EQ(run("tree beech --bogus").exitCode, 2);
  RunResult badFormat = run("tree beech --out " + (dir / "x.fbx").string());
  EXPECT_EQ(badFormat.exitCode, 2);
  EXPECT_NE(badFormat.output.find("unknown output format"), std::string::npos);
  RunResult missingFolder = run("tree beech --out /nonexistent/dir/x.glb");
  EXPECT_EQ(missingFolder.exitCode, 2);
  EXPECT_NE(missingFolder.output.find("/nonexistent/dir/x.glb: cannot write this file"),
            std::string::npos)
      << missingFolder.output;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  RunResult missingFile = run("tree /nonexistent/oak.toml");
  EXPECT_EQ(missingFile.exitCode, 2);
  EXPECT_NE(missingFile.output.find("/nonexistent/oak.toml: cannot open file"), std::string::npos);
}

TEST(TreeCommand, HelpAndVersionExitZero) {
  EXPECT_EQ(run("--help").exitCode, 0);
  EXPECT_EQ(run("tree --help").exitCode, 0);
  RunResult version = run("--version");
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_NE(version.output.find("ecoforest"), std::string::npos);
}
