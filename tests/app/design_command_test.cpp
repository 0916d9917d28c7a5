// Runs `ecoforest design` as a user would: headless with a file of edits, and its window
// under a virtual X server with a real pointer drag.
#include <fstream>
#include <sstream>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app_support.hpp"

namespace {

using eco::test::CommandResult;
using eco::test::ecoforest;

std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::filesystem::path writeFile(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
  return file;
}

nlohmann::json treeStats(const std::string& species) {
  const CommandResult r = ecoforest("tree " + species + " --stats");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return nlohmann::json::parse(r.output);
}

// The walk-through of docs/designer.md: the paper's beech to a broad open-grown beech.
const std::string kBroadBeech = std::string(ECOFOREST_DATA_DIR) + "/edits/broad_beech.toml";

TEST(DesignCommand, AppliesEditsSavesTheSpeciesAndScreenshotsTheDesigner) {
  const auto dir = eco::test::freshDirectory("app_design");
  const std::string edits = kBroadBeech;
  const CommandResult r =
      ecoforest("design beech --apply " + edits + " --save " + (dir / "broad_beech.toml").string() +
                " --screenshot " + (dir / "designer.png").string() + " --size 1280x720 --export " +
                (dir / "broad.glb").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("6 edits applied"), std::string::npos) << r.output;
  const std::string saved = readText(dir / "broad_beech.toml");
  EXPECT_NE(saved.find("trunk_length_m = 2.5"), std::string::npos) << saved;
  EXPECT_NE(saved.find("alpha_g_deg = [[0.0, 62.0], [15.0, 50.0]]"), std::string::npos) << saved;
  EXPECT_NE(saved.find("ks_g = [[0.0, 0.75], [2.0, 0.62], [15.0, 0.9]]"), std::string::npos)
      << saved;
  EXPECT_NE(saved.find("[ecology.life]"), std::string::npos);  // it still grows in a run
  // The saved species is a species: `ecoforest tree` builds it, broader than the beech.
  const nlohmann::json beech = treeStats("beech"),
                       broad = treeStats((dir / "broad_beech.toml").string());
  EXPECT_EQ(broad["segments"], beech["segments"]);
  // docs/designer.md: a crown radius of 10.8 m against the beech's 7.3.
  EXPECT_NEAR(broad["crown_radius_m"].get<double>(), 10.8, 0.05);
  EXPECT_NEAR(beech["crown_radius_m"].get<double>(), 7.3, 0.05);
  EXPECT_GT(std::filesystem::file_size(dir / "broad.glb"), 100000u);

  auto in = OIIO::ImageInput::open((dir / "designer.png").string());
  ASSERT_TRUE(in);
  ASSERT_EQ(in->spec().width, 1280);
  ASSERT_EQ(in->spec().height, 720);
  std::vector<unsigned char> pixels(1280 * 720 * in->spec().nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT8, pixels.data()));
  int orange = 0;  // the hint: the trunk and limbs of g = 0..2 in the hint colour
  for (std::size_t p = 0; p < pixels.size(); p += in->spec().nchannels)
    orange += pixels[p] > 90 && pixels[p] > 2 * pixels[p + 1] && pixels[p + 1] > 2 * pixels[p + 2];
  EXPECT_GT(orange, 1000);
}

TEST(DesignCommand, TheSameEditsGiveTheSameFileEveryTime) {
  const auto dir = eco::test::freshDirectory("app_design_same");
  const std::string edits = kBroadBeech;
  for (const char* name : {"a.toml", "b.toml"})
    ASSERT_EQ(
        ecoforest("design beech --apply " + edits + " --save " + (dir / name).string()).exitCode,
        0);
  EXPECT_EQ(readText(dir / "a.toml"), readText(dir / "b.toml"));
}

TEST(DesignCommand, BadEditsNameTheirLineAndWriteNothing) {
  const auto dir = eco::test::freshDirectory("app_design_bad");
  const auto edits =
      writeFile(dir / "edits.toml",
                "[[edit]]\nset = \"kc\"\nvalue = 0.5\n\n[[edit]]\ngraph = \"ks_g\"\nremove = 7\n");
  CommandResult r = ecoforest("design beech --apply " + edits.string() + " --save " +
                              (dir / "out.toml").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("edits.toml:6: edit[1].graph: ks_g has no point 7"), std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.toml"));
  r = ecoforest("design beech --apply " + kBroadBeech + " --name 'broad beech'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("cannot name a species"), std::string::npos) << r.output;
  r = ecoforest("design birch --apply " + edits.string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("RL-system"), std::string::npos) << r.output;
}

TEST(DesignCommand, ADesignedSpeciesGrowsInARun) {
  const auto dir = eco::test::freshDirectory("app_design_run");
  const std::string edits = kBroadBeech;
  ASSERT_EQ(ecoforest("design beech --apply " + edits + " --name broad_beech --save " +
                      (dir / "broad_beech.toml").string())
                .exitCode,
            0);
  const auto scenario = writeFile(dir / "broad.toml", R"(name = "broad"
seed = 3
[terrain.generate]
method = "midpoint"
size = 33
roughness = 0.5
relief_m = 20.0
base_altitude_m = 400.0
[terrain]
cell_size_m = 8.0
[simulation]
years = 8
[[species]]
file = "broad_beech.toml"
seed_rain_per_ha_per_year = 5.0
[output]
snapshot_every_years = 4
)");
  const CommandResult r =
      ecoforest("run " + scenario.string() + " --out " + (dir / "run").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string trees = readText(dir / "run" / "trees" / "year_0008.csv");
  EXPECT_NE(trees.find("broad_beech"), std::string::npos) << trees.substr(0, 400);
}

TEST(DesignCommand, WithoutADisplayTheWindowSaysSoAndExitsThree) {
  const CommandResult r = eco::test::runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " +
                                                std::string(ECOFOREST_EXE) + " design beech");
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_NE(r.output.find("`design` needs a display"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--apply"), std::string::npos) << r.output;
}

// The window under Xvfb: a real pointer drag on the m^g graph's middle point and Ctrl+S.
TEST(DesignCommand, AWindowDragOnAGraphChangesTheSavedSpecies) {
  for (const char* tool : {"xvfb-run", "xdotool"})
    if (eco::test::runCommand(std::string("command -v ") + tool).exitCode != 0)
      GTEST_SKIP() << tool << " is not installed (scripts/test installs xvfb and xdotool)";
  const auto dir = eco::test::freshDirectory("app_design_window");
  const CommandResult r = eco::test::runCommand(
      std::string(ECOFOREST_X_WINDOW_ENV) + "xvfb-run -a -s '-screen 0 1600x900x24' " +
      ECOFOREST_SOURCE_DIR + "/tests/app/tools/design_drag.sh " + ECOFOREST_EXE + " " +
      dir.string() + " min_length_g 1 30");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_TRUE(std::filesystem::exists(dir / "dragged.toml")) << r.output;
  const std::string saved = readText(dir / "dragged.toml");
  const std::string prefix = "min_length_g = [[0.0, 1.0], [7.5, ";
  const std::size_t at = saved.find(prefix);
  ASSERT_NE(at, std::string::npos) << saved;
  // 30 pixels up a graph 84 pixels tall over [0, 10]: from 0.45 to about 4.
  const double y = std::stod(saved.substr(at + prefix.size()));
  EXPECT_GT(y, 3.0) << saved;
  EXPECT_LT(y, 5.0) << saved;
}

}  // namespace
