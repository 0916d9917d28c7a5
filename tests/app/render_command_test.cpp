// Runs `ecoforest render` and `ecoforest view` as a user would.
#include <cstdlib>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app_support.hpp"
#include "core/image_metrics.hpp"
#include "sim/image_io.hpp"

namespace {

using eco::test::CommandResult;
using eco::test::ecoforest;
using eco::test::shortDefaultRun;

std::pair<int, int> pngSize(const std::filesystem::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return {0, 0};
  return {in->spec().width, in->spec().height};
}

TEST(RenderCommand, ARunFolderRendersAStillWithItsStatistics) {
  const auto out = eco::test::freshDirectory("app_render") / "still.png";
  CommandResult r = ecoforest("render " + shortDefaultRun().string() +
                              " --year 20 --size 320x180 --stats --out " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(pngSize(out), std::make_pair(320, 180));
  const auto json = nlohmann::json::parse(r.output.substr(r.output.find('{')));
  std::size_t drawn = 0;
  for (const char* level : {"lod0", "lod1", "lod2", "impostor"})
    drawn += json["instances"][level].get<std::size_t>();
  EXPECT_GT(drawn, 0u);
  EXPECT_GT(json["tree_triangles_all_lod0"].get<double>(), json["tree_triangles"].get<double>());
  EXPECT_GT(json["frame_ms"].get<double>(), 0.0);
  EXPECT_GT(json["tree_gpu_mib"]["meshes"].get<double>(), 0.0);
  EXPECT_GT(json["tree_gpu_mib"]["impostors"].get<double>(), 0.0);
}

TEST(RenderCommand, AScenarioRendersItsTerrainWithAnOverlay) {
  const auto out = eco::test::freshDirectory("app_render_terrain") / "terrain.png";
  CommandResult r = ecoforest(
      "render default --size 200x120 --overlay altitude --camera 500,100,800,0,-30 --out " +
      out.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(pngSize(out), std::make_pair(200, 120));
}

// --antialias 4 draws the same picture with smoother edges: it differs from the aliased one
// only along edges (a small mean difference). The default, auto, draws no samples on
// llvmpipe, where the tests run, and --stats says how many a pixel were drawn. (A sample
// count beyond the driver's is an EnvironmentError, exit 3: gl_objects_test.)
TEST(RenderCommand, AntialiasingSmoothsEdgesOfTheSamePicture) {
  const auto dir = eco::test::freshDirectory("app_render_antialias");
  const std::string still =
      "render default --demo-trees 20 --size 320x180 --view low --quality draft --stats";
  CommandResult plain = ecoforest(still + " --out " + (dir / "1.png").string());
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  CommandResult smooth = ecoforest(still + " --antialias 4 --out " + (dir / "4.png").string());
  ASSERT_EQ(smooth.exitCode, 0) << smooth.output;
  EXPECT_NE(smooth.output.find("\"antialias_samples\": 4"), std::string::npos) << smooth.output;
  if (plain.output.find("llvmpipe") != std::string::npos) {
    EXPECT_NE(plain.output.find("\"antialias_samples\": 1"), std::string::npos) << plain.output;
  }
  const eco::Image a = eco::readColorImage(dir / "1.png"), b = eco::readColorImage(dir / "4.png");
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  std::size_t changed = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
    changed += std::abs(int(a.rgba[i]) - int(b.rgba[i])) > 8;
  EXPECT_GT(changed, a.rgba.size() / 1000) << "anti-aliasing changed nothing";
  EXPECT_LT(eco::meanAbsoluteDifference(a, b), 6.0);
}

// The impostor atlases a still bakes are kept in the user's cache folder
// (ECOFOREST_CACHE_DIR here), and the next still of the same trees reads them instead: the
// same picture, byte for byte. A cache folder that cannot be made warns and draws anyway.
TEST(RenderCommand, TheNextStillOfTheSameTreesReadsItsImpostorsFromTheCache) {
  const auto dir = eco::test::freshDirectory("app_render_cache");
  const std::string still =
      "render " + shortDefaultRun().string() + " --year 20 --size 320x180 --stats --out ";
  auto atlases = [](const CommandResult& r) {
    const auto json = nlohmann::json::parse(r.output.substr(r.output.find('{')));
    return std::pair(json["impostor_atlases"]["baked"].get<int>(),
                     json["impostor_atlases"]["from_cache"].get<int>());
  };
  setenv("ECOFOREST_CACHE_DIR", (dir / "cache").c_str(), 1);
  CommandResult first = ecoforest(still + (dir / "1.png").string());
  CommandResult second = ecoforest(still + (dir / "2.png").string());
  eco::test::writeFile(dir / "a file", "in the way of the cache folder");
  setenv("ECOFOREST_CACHE_DIR", (dir / "a file" / "cache").c_str(), 1);
  CommandResult blocked = ecoforest(still + (dir / "3.png").string());
  setenv("ECOFOREST_CACHE_DIR", "off", 1);  // as the suite runs (tests/CMakeLists.txt)
  ASSERT_EQ(first.exitCode, 0) << first.output;
  ASSERT_EQ(second.exitCode, 0) << second.output;
  const auto [baked, none] = atlases(first);
  EXPECT_GT(baked, 0);
  EXPECT_EQ(none, 0);
  EXPECT_EQ(atlases(second), std::pair(0, baked));
  EXPECT_EQ(eco::test::readFile(dir / "1.png"), eco::test::readFile(dir / "2.png"));
  ASSERT_EQ(blocked.exitCode, 0) << blocked.output;
  EXPECT_NE(blocked.output.find("warning: cannot keep results in the cache folder"),
            std::string::npos)
      << blocked.output;
  EXPECT_EQ(eco::test::readFile(dir / "1.png"), eco::test::readFile(dir / "3.png"));
}

// On a terminal (here a pseudo-terminal of util-linux's `script`) each slow step of a still
// says what it does, and the impostors' baking shows its progress; elsewhere (every other
// test) nothing of it is printed.
TEST(RenderCommand, OnATerminalEachSlowStepSaysWhatItDoes) {
  if (eco::test::runCommand("command -v script").exitCode != 0)
    GTEST_SKIP() << "util-linux's script is not installed";
  const auto out = eco::test::freshDirectory("app_render_terminal") / "still.png";
  const std::string still = "render " + shortDefaultRun().string() +
                            " --year 20 --quality draft --size 320x180 --out " + out.string();
  const CommandResult r = eco::test::runCommand("script -qec '" + std::string(ECOFOREST_EXE) + " " +
                                                still + "' /dev/null");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* line : {"render: reading year 20", "render: drawing ", "at draft quality",
                           "impostor atlases", "done", "render: wrote"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line << " in:\n" << r.output;
  const CommandResult plain = ecoforest(still);
  EXPECT_EQ(plain.output.find("render:"), std::string::npos) << plain.output;
}

TEST(RenderCommand, BadInputIsExitTwoWithAClearMessageAndNoFile) {
  const auto dir = eco::test::freshDirectory("app_render_bad");
  const std::string out = " --out " + (dir / "x.png").string();
  CommandResult missing = ecoforest("render " + (dir / "no_such_run").string() + out);
  EXPECT_EQ(missing.exitCode, 2) << missing.output;
  CommandResult notRun = ecoforest("render " + dir.string() + out);
  EXPECT_EQ(notRun.exitCode, 2);
  EXPECT_NE(notRun.output.find("no run.json"), std::string::npos) << notRun.output;
  CommandResult year = ecoforest("render " + shortDefaultRun().string() + " --year 7" + out);
  EXPECT_EQ(year.exitCode, 2);
  EXPECT_NE(year.output.find("has: 10, 20"), std::string::npos) << year.output;
  CommandResult camera = ecoforest("render default --camera 1,2,3" + out);
  EXPECT_EQ(camera.exitCode, 2);
  EXPECT_NE(camera.output.find("--camera"), std::string::npos) << camera.output;
  CommandResult size = ecoforest("render default --size 12x9000" + out);
  EXPECT_EQ(size.exitCode, 2);
  CommandResult samples = ecoforest("render default --antialias 3" + out);
  EXPECT_EQ(samples.exitCode, 2);
  EXPECT_NE(samples.output.find("--antialias"), std::string::npos) << samples.output;
  CommandResult unwritable =
      ecoforest("render default --out " + (dir / "missing" / "x.png").string());
  EXPECT_EQ(unwritable.exitCode, 2);
  EXPECT_NE(unwritable.output.find("folder does not exist"), std::string::npos);
  CommandResult overlay =
      ecoforest("render " + shortDefaultRun().string() + " --overlay nonsense" + out);
  EXPECT_EQ(overlay.exitCode, 2);
  EXPECT_NE(overlay.output.find("moisture"), std::string::npos) << overlay.output;
  EXPECT_EQ(eco::test::entriesIn(dir), 0u);
}

TEST(RenderCommand, AFullDiskOrAReadOnlyFolderIsAClearErrorAndLeavesNothing) {
  eco::test::expectFullAndReadOnlyDisksFailCleanly(
      // draft: the test is about the file, not the picture, and runs the command often.
      "render " + shortDefaultRun().string() +
          " --size 640x360 --quality draft --out \"$SPACE/a.png\"",
      16, "a.png: writing failed: No space left on device");
}

// Ctrl-C at any moment of a render: it either finished (exit 0, the whole picture) or
// stopped (exit 130, no picture), and never leaves a temporary.
TEST(RenderCommand, CtrlCLeavesNothingPartial) {
  const auto dir = eco::test::freshDirectory("app_render_interrupt");
  for (const char* after : {"0.3", "1", "2"}) {
    CommandResult r = eco::test::interruptWhen("render " + shortDefaultRun().string() +
                                                   " --size 1920x1080 --quality draft --out " +
                                                   (dir / "a.png").string(),
                                               std::string("sleep ") + after);
    EXPECT_TRUE(r.exitCode == 130 || r.exitCode == 0) << after << ": " << r.output;
    // The whole picture or nothing, and no temporary: a Ctrl-C that comes after the picture
    // was renamed into place, as the process exits, leaves it there (whole).
    const bool done = std::filesystem::exists(dir / "a.png");
    if (r.exitCode == 0 || done) {
      EXPECT_EQ(pngSize(dir / "a.png"), std::make_pair(1920, 1080)) << after;
    }
    EXPECT_EQ(eco::test::entriesIn(dir), done ? 1u : 0u) << after;
    std::filesystem::remove(dir / "a.png");
  }
}

// `view` of the short default run in a 400 x 300 window under a virtual X server, its
// screenshot written to `shot`. Skipped where Xvfb is not installed.
class ViewWindow : public testing::Test {
 protected:
  void SetUp() override {
    if (eco::test::runCommand("command -v xvfb-run").exitCode != 0)
      GTEST_SKIP() << "xvfb-run is not installed (Debian: xvfb); the view window is not tested";
  }
  static CommandResult view(const std::string& options, const std::filesystem::path& shot) {
    return eco::test::runCommand(std::string(ECOFOREST_X_WINDOW_ENV) +
                                 "xvfb-run -a -s '-screen 0 800x600x24' " + ECOFOREST_EXE +
                                 " view " + shortDefaultRun().string() + " --size 400x300 " +
                                 options + " --screenshot " + shot.string());
  }
};

// The window opens, draws a few frames, saves a screenshot and exits.
TEST_F(ViewWindow, OpensDrawsFramesAndSavesAScreenshot) {
  const auto shot = eco::test::freshDirectory("app_view") / "view.png";
  const CommandResult r = view("--frames 4 --view ground", shot);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(pngSize(shot), std::make_pair(400, 300));
}

// A frame-time target no frame can reach: the view coarsens the levels, then draws fewer
// pixels down to a quarter of the window's width and height, says so, and its screenshot is
// still the window's full size.
TEST_F(ViewWindow, AnUnreachableTargetLowersTheResolutionButNotTheScreenshots) {
  const auto shot = eco::test::freshDirectory("app_view_budget") / "view.png";
  const CommandResult r = view("--frames 14 --target-fps 1000 --view low", shot);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("14 frames"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("not reachable): LOD sizes x64.00, resolution 25 %"), std::string::npos)
      << r.output;
  EXPECT_EQ(pngSize(shot), std::make_pair(400, 300));
}

// A missing display is the machine's, not the input's: exit code 3 (README, "Exit codes").
TEST(ViewCommand, WithoutADisplayItSaysSoAndExitsThree) {
  CommandResult r = eco::test::runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " +
                                          std::string(ECOFOREST_EXE) + " view default");
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_NE(r.output.find("needs a display"), std::string::npos) << r.output;
}

}  // namespace
