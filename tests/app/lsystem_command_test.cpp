// `ecoforest lsystem`, and L-system species in `tree`, `run`, `render` and `export`.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app_support.hpp"

namespace eco::test {
namespace {

std::filesystem::path grammarFile(const std::string& name, const std::string& text) {
  const std::filesystem::path file = freshDirectory("lsystem_" + name) / (name + ".lsys");
  writeFile(file, text);
  return file;
}

TEST(LSystemCommand, PrintWritesOnlyTheDerivedString) {
  const CommandResult r = ecoforest("lsystem green_example --seed 3 --print 2>/dev/null");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.output, "A(2)B(6)[A(3)]B(4)\n");
  EXPECT_EQ(ecoforest("lsystem lecture_monopodial --iterations 2 --print").output,
            "11[11[0]0]11[0]0\n");
}

TEST(LSystemCommand, StatsAreJsonWithCountsAndTimings) {
  const CommandResult r = ecoforest("lsystem abop_1_24a --iterations 4 --stats");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const nlohmann::json stats = nlohmann::json::parse(r.output);
  EXPECT_EQ(stats["iterations"], 4);
  EXPECT_EQ(stats["segments"], 625);                          // 5^4 F
  EXPECT_EQ(stats["modules"], 625 + 6 * (1 + 5 + 25 + 125));  // each F makes 6 [ ] + -
  for (const char* key : {"leaves", "derivation_ms", "interpretation_ms", "modules_rewritten"})
    EXPECT_TRUE(stats.contains(key)) << key;
}

TEST(LSystemCommand, ExportsTheTreeInEveryFormat) {
  const auto folder = freshDirectory("lsystem_export");
  for (const char* extension : {".glb", ".obj", ".pov", ".wrl"}) {
    const auto out = folder / (std::string("ternary") + extension);
    const CommandResult r = ecoforest("lsystem green_ternary --out " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_GT(std::filesystem::file_size(out), 10000u) << extension;
  }
}

TEST(LSystemCommand, BadGrammarsExitWithTwoAndTheirPlace) {
  const auto bad = grammarFile("bad", "SYSTEM\nAXIOM\n  A\nRULES\n  A -> B(1,\nEND.\n");
  CommandResult r = ecoforest("lsystem " + bad.string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find(bad.string() + ":5:12: expected an expression"), std::string::npos)
      << r.output;

  const auto bomb = grammarFile("bomb", "SYSTEM\nAXIOM\n  F\nRULES\n  F -> FF\nEND.\n");
  r = ecoforest("lsystem " + bomb.string() + " --iterations 40 --max-modules 100000");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find(":5: derivation step 17 makes more than 100000 modules"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("'F -> FF' exploded"), std::string::npos) << r.output;

  EXPECT_EQ(ecoforest("lsystem no_such_grammar").exitCode, 2);
  const auto out = freshDirectory("lsystem_bad_out") / "tree.txt";
  r = ecoforest("lsystem abop_1_24a --out " + out.string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(ecoforest("lsystem abop_1_24a --print --stats").exitCode, 2);
}

TEST(LSystemCommand, LSystemSpeciesWorkInTreeRunRenderAndExport) {
  const CommandResult tree = ecoforest("tree birch --stats");
  ASSERT_EQ(tree.exitCode, 0) << tree.output;
  const nlohmann::json stats = nlohmann::json::parse(tree.output);
  EXPECT_EQ(stats["generator"], "lsystem");
  EXPECT_GT(stats["height_m"].get<double>(), 15.0);

  const auto folder = freshDirectory("lsystem_grove");
  const auto run = folder / "run";
  CommandResult r = ecoforest("run birch_grove --years 20 --out " + run.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string trees = readFile(run / "trees" / "year_0020.csv");
  EXPECT_NE(trees.find(",birch,"), std::string::npos);

  const auto still = folder / "grove.png";
  r = ecoforest("render " + run.string() + " --view low --size 160x90 --out " + still.string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(still));

  const auto glb = folder / "grove.glb";
  r = ecoforest("export " + run.string() + " --out " + glb.string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_GT(std::filesystem::file_size(glb), 10000u);
}

}  // namespace
}  // namespace eco::test
