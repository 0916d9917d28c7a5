#include "render/timelapse.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "render_support.hpp"
#include "core/angles.hpp"

namespace eco {
namespace {

class CollectingSink : public FrameSink {
 public:
  void add(const Image& frame) override { frames.push_back(frame); }
  void finish() override { finished = true; }
  std::vector<Image> frames;
  bool finished = false;
};

TEST(Timelapse, FramesSpanTheYearsEvenly) {
  TimelapseSettings s;
  s.fromYear = 0;
  s.toYear = 60;
  s.seconds = 2.0;
  s.fps = 10;
  EXPECT_EQ(s.frameCount(), 20);
  EXPECT_DOUBLE_EQ(s.yearOfFrame(0), 0.0);
  EXPECT_DOUBLE_EQ(s.yearOfFrame(19), 60.0);
  EXPECT_NEAR(s.yearOfFrame(10), 60.0 * 10 / 19, 1e-12);
  s.kind = TimelapseKind::Wind;
  s.fromYear = s.toYear = 30;
  EXPECT_DOUBLE_EQ(s.yearOfFrame(7), 30.0);
}

TEST(Timelapse, TheScaleBarMeasuresTheGroundAtTheCentre) {
  const Terrain terrain = test::flatTerrain(65, 10.0);
  Camera camera;
  camera.position = worldFromMap(320, 320, 600);  // 500 m above the ground
  camera.pitch_deg = -90.0f;
  EXPECT_NEAR(metresPerPixelAtCentre(camera, terrain, 500),
              2.0 * 500.0 * std::tan(radians(25.0)) / 500.0, 0.02);
  Image frame(200, 100);
  const Image blank = frame;
  drawOverlay(frame, 12.0, 1.0);
  EXPECT_GT(test::compareImages(frame, blank).differingShare, 0.01);
}

// A single maple planted at year 0 grows through three snapshots; its silhouette in a fixed
// view grows frame after frame (allowing for the dither of age-class blends).
TEST(Timelapse, ASingleTreesSilhouetteGrowsFrameByFrame) {
  test::useHeadlessGl();
  const auto dir = test::freshDirectory("timelapse_run");
  std::filesystem::create_directories(dir / "trees");
  const char* header =
      "id,species,x_m,y_m,z_m,age,height_m,crown_radius_m,dbh_m,vigor,variant_seed\n";
  const std::pair<int, double> sizes[] = {{10, 2.0}, {20, 6.0}, {30, 11.0}};
  RunFolder run;
  run.dir = dir;
  for (auto [year, height] : sizes) {
    test::writeFile(dir / "trees" / fmt::format("year_{:04d}.csv", year),
                    std::string(header) + fmt::format("1,maple,160,160,100,{},{},{},0.1,0.9,1\n",
                                                      year - 2, height, 0.3 * height));
    run.snapshotYears.push_back(year);
  }
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer renderer(terrain, 46.0, &test::smallLibrary());
  TimelapseSettings settings;
  settings.fromYear = 8.0;  // the tree established in year 8
  settings.toYear = 30.0;
  settings.seconds = 1.2;
  settings.fps = 10;
  settings.frame = {96, 96};
  settings.render.shadows = false;
  settings.camera = [](double) {
    return lookingAt(worldFromMap(160, 130, 106), worldFromMap(160, 160, 105));
  };
  CollectingSink sink;
  const TimelapseTimings t =
      renderTimelapse(run, test::smallLibrary(), renderer, settings, sink, {});
  ASSERT_EQ(t.frames, 12);
  ASSERT_EQ(sink.frames.size(), 12u);
  EXPECT_TRUE(sink.finished);
  Forest empty;
  const RenderTarget target = RenderTarget::create(96, 96);
  renderer.render(&empty, settings.camera(0.0), settings.render, target);
  const Image background = readPixels(96, 96);
  double previous = 0.0;
  for (std::size_t f = 0; f < sink.frames.size(); ++f) {
    const double area = test::compareImages(sink.frames[f], background).differingShare;
    EXPECT_GE(area, previous * 0.95) << "frame " << f;
    previous = std::max(previous, area);
  }
  EXPECT_GT(previous, 5.0 * test::compareImages(sink.frames[1], background).differingShare);
}

}  // namespace
}  // namespace eco
