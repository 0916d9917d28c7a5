#include "render/scene/timelapse.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "core/angles.hpp"
#include "core/error.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/growth_timeline.hpp"
#include "render/scene/tree_clearance.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

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

// Two snapshots of a one-tree run (the tree appears in year 15), for frames without OpenGL.
RunFolder oneTreeRun(const std::string& name) {
  const auto dir = test::freshDirectory(name);
  std::filesystem::create_directories(dir / "trees");
  RunFolder run;
  run.dir = dir;
  for (auto [year, height] : {std::pair{10, 0.0}, {20, 4.0}}) {
    std::string rows = std::string(kTreesCsvHeaderWithoutSite) + "\n";
    if (height > 0.0) rows += fmt::format("1,maple,160,160,100,5,{},1.0,1.5,0.05,0.9,1\n", height);
    test::writeFile(RunPaths{dir}.snapshot(year, SnapshotFormat::Csv), rows);
    run.snapshotYears.push_back(year);
  }
  return run;
}

// The loop without a back end: what each frame is asked to draw.
struct Recorded {
  std::vector<std::size_t> trees;
  std::vector<float> crownArea;  // the floor's, in cell areas
  std::vector<double> windTimes;
  std::vector<glm::vec3> eyes;
};

// A growth time-lapse of the one-tree run with a frame a year: 21 frames, years 0 to 20.
TimelapseSettings yearlyGrowthFrames() {
  TimelapseSettings settings;
  settings.toYear = 20.0;
  settings.seconds = 2.1;
  settings.fps = 10;
  settings.frame = {32, 24};
  return settings;
}

TEST(Timelapse, GrowthAsksEachFrameForTheForestOfItsYear) {
  const RunFolder run = oneTreeRun("timelapse_growth");
  const Terrain terrain = test::flatTerrain(33, 10.0);
  TimelapseSettings settings = yearlyGrowthFrames();
  settings.camera = [](double u) {
    return lookingAt(worldFromMap(100 + 100 * u, 10, 300), worldFromMap(160, 160, 100));
  };
  Recorded seen;
  const DrawFrame draw = [&](const FrameTrees& trees, const Camera& camera,
                             const RenderOptions& o) {
    seen.trees.push_back(trees.shown.size());
    float area = 0.0f;
    for (const auto& below : trees.floor.crownsBelow) area += below.back();
    seen.crownArea.push_back(area);
    seen.windTimes.push_back(o.wind.time);
    seen.eyes.push_back(camera.position);
    EXPECT_EQ(trees.index, nullptr);  // a frame's trees are its own
    return Image(32, 24);
  };
  test::CollectingSink sink;
  const TimelapseTimings t =
      renderTimelapse(run, test::smallLibrary(), terrain, draw, settings, sink, {});
  ASSERT_EQ(t.frames, 21);
  EXPECT_EQ(sink.frames.size(), 21u);
  EXPECT_TRUE(sink.finished);
  // Before the tree established (year 15: age 5 in year 20) nothing is there; from then on
  // the one tree grows, its crown on the floor. From 250 m on a frame 24 pixels high it is
  // under a pixel even at 4 m, so the renderer would draw nothing of it: the frame leaves it
  // out of the trees it shows.
  for (int frame = 0; frame < 21; ++frame) {
    EXPECT_EQ(seen.trees[frame], 0u) << "year " << frame;
    if (frame <= 15) {  // it appears over its first year
      EXPECT_EQ(seen.crownArea[frame], 0.0f) << "year " << frame;
    } else {
      EXPECT_GT(seen.crownArea[frame], seen.crownArea[frame - 1]) << "year " << frame;
    }
  }
  EXPECT_EQ(seen.windTimes.front(), seen.windTimes.back());  // growth holds the wind's time
  EXPECT_NEAR(seen.eyes.back().x - seen.eyes.front().x, 100.0f, 1e-3f);  // along the path
}

// A path set through the place where a tree grows later is lifted out of its crown: every
// frame's eye keeps kGroundClearance_m from the trees that frame draws, and is not moved
// while there is nothing in the way.
TEST(Timelapse, ThePathKeepsClearOfTheCrownsOfEachFrame) {
  const RunFolder run = oneTreeRun("timelapse_clearance");
  const Terrain terrain = test::flatTerrain(33, 10.0);
  TimelapseSettings settings = yearlyGrowthFrames();
  const glm::vec3 inTheCrown = worldFromMap(160, 160, 102.5);  // the tree is 4 m tall at 20
  settings.camera = [&](double) { return lookingAt(inTheCrown, worldFromMap(160, 300, 102.5)); };
  std::vector<float> clearance;
  std::vector<glm::vec3> eyes;
  const DrawFrame draw = [&](const FrameTrees& trees, const Camera& camera, const RenderOptions&) {
    clearance.push_back(
        TreeClearance(trees.shown, test::smallLibrary()).at(camera.position, 10.0f));
    eyes.push_back(camera.position);
    return Image(32, 24);
  };
  test::CollectingSink sink;
  renderTimelapse(run, test::smallLibrary(), terrain, draw, settings, sink, {});
  ASSERT_EQ(eyes.size(), 21u);
  for (std::size_t frame = 0; frame < eyes.size(); ++frame) {
    EXPECT_GE(clearance[frame], kGroundClearance_m) << "year " << frame;
    if (frame < 15) {  // no tree yet
      EXPECT_EQ(eyes[frame], inTheCrown) << "year " << frame;
    }
  }
  EXPECT_GT(eyes.back().y, inTheCrown.y + 1.0f);  // lifted over the grown crown
  EXPECT_EQ(eyes.back().x, inTheCrown.x);         // straight up, the view kept
}

// A growth frame holds only the trees the renderer may draw from its camera, made a part at
// a time; the floor holds the crowns of all of them, the same to the bit as the floor of the
// whole frame's forest.
TEST(Timelapse, AFrameLeavesOutTheTreesUnderAPixelButNotTheirCrowns) {
  const TreeLibrary& library = test::smallLibrary();
  TreeSnapshot before, after;
  before.year = 10, after.year = 20;
  before.speciesNames = after.speciesNames = {"beech"};
  // More trees than a part of a frame, 1 km across, most of them young plants.
  for (std::uint64_t id = 1; id <= (std::uint64_t{1} << 20) + 3000; ++id) {
    after.trees.push_back(test::mostlyYoungTree(id));
    if (id % 3 != 0) {  // the others establish in between
      before.trees.push_back(after.trees.back());
      before.trees.back().height_m *= 0.8f;
    }
  }
  const RunFolder run =
      test::runHolding("timelapse_frame_parts", {&before, &after}, SnapshotFormat::Binary);
  const Terrain terrain = test::flatTerrain(106, 10.0);
  TimelapseSettings settings;
  settings.fromYear = settings.toYear = 16.0;
  settings.seconds = 0.1, settings.fps = 10;  // one frame
  settings.frame = {640, 360};
  const Camera camera = lookingAt(worldFromMap(0, 0, 420), worldFromMap(500, 500, 300));
  settings.camera = [&](double) { return camera; };
  std::size_t shownTrees = 0;
  std::optional<CanopyFloor> floor;
  std::vector<glm::vec3> shownAt;
  const DrawFrame draw = [&](const FrameTrees& trees, const Camera& drawn, const RenderOptions&) {
    EXPECT_EQ(drawn.position, camera.position);  // no tree near the eye
    shownTrees = trees.shown.size();
    shownAt = trees.shown.position;
    floor = trees.floor;
    return Image(640, 360);
  };
  test::CollectingSink sink;
  renderTimelapse(run, library, terrain, draw, settings, sink, {});
  ASSERT_TRUE(floor);

  const Forest whole = GrowthInterval(before, after, library, "run").forestAt(16.0);
  const CanopyFloor wholeFloor = canopyFloor(whole, library, terrain.grid);
  EXPECT_EQ(floor->crownsBelow, wholeFloor.crownsBelow);
  EXPECT_EQ(floor->leafColor, wholeFloor.leafColor);
  // The trees shown are the whole frame's in its order, less those under a pixel from any
  // eye the path's could be lifted to.
  const LodSettings lod;
  const float pixelsPerRadian = camera.pixelsPerRadian(settings.frame.height);
  std::size_t drawn = 0, next = 0;
  for (std::size_t i = 0; i < whole.size(); ++i) {
    const TreeType& type = library.type(whole.type[i]);
    const float height = type.height_m * whole.scaleY[i];
    const float distance = glm::length(glm::vec3(drawnBounds(whole, i, type)) - camera.position);
    const bool shown = next < shownAt.size() && shownAt[next] == whole.position[i];
    if (shown) ++next;
    if (!tooSmallToDraw(projectedPixels(height, distance, pixelsPerRadian), lod)) {
      EXPECT_TRUE(shown) << "tree " << i << " is drawn from the camera";
      ++drawn;
    }
    // (A tree within a thousandth of a pixel's size may be kept: mayBeDrawn's margin.)
    if (tooSmallToDraw(projectedPixels(1.002f * height, distance - kMaxLift_m, pixelsPerRadian),
                       lod)) {
      EXPECT_FALSE(shown) << "tree " << i << " is under a pixel from every lifted eye";
    }
  }
  EXPECT_EQ(next, shownTrees);  // in order, nothing else
  EXPECT_GT(drawn, 1000u);
  EXPECT_LT(shownTrees, whole.size() / 2);
}

// Two snapshots whose trees would not fit in the memory there is are refused before they are
// paired, with the years and the way to go ahead; told to go ahead, it does (and fails
// otherwise: a terabyte of nothing, sparse, is neither room to be had nor a snapshot).
TEST(Timelapse, AnIntervalTooLargeForTheMemoryIsRefusedBeforeItIsPaired) {
  RunFolder run = oneTreeRun("timelapse_memory");
  std::filesystem::remove(RunPaths{run.dir}.snapshot(20, SnapshotFormat::Csv));
  const std::filesystem::path huge = RunPaths{run.dir}.snapshot(20, SnapshotFormat::Binary);
  test::writeFile(huge, "");
  std::filesystem::resize_file(huge, std::uintmax_t{1} << 40);
  TimelapseSettings settings;
  settings.fromYear = settings.toYear = 15.0;
  settings.seconds = 0.1, settings.fps = 10;  // one frame, between years 10 and 20
  settings.camera = [](double) { return Camera{}; };
  int drawn = 0;
  const DrawFrame draw = [&](const FrameTrees&, const Camera&, const RenderOptions&) {
    ++drawn;
    return Image(16, 16);
  };
  test::CollectingSink sink;
  const Terrain terrain = test::flatTerrain(33, 10.0);
  try {
    renderTimelapse(run, test::smallLibrary(), terrain, draw, settings, sink, {});
    ADD_FAILURE() << "no refusal";
  } catch (const EnvironmentError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("between the snapshots of years 10 and 20"), std::string::npos) << text;
    EXPECT_NE(text.find("--ignore-memory-check"), std::string::npos) << text;
  }
  settings.ignoreMemoryCheck = true;
  try {
    renderTimelapse(run, test::smallLibrary(), terrain, draw, settings, sink, {});
    ADD_FAILURE() << "a terabyte of nothing was read as trees";
  } catch (const EnvironmentError& e) {
    ADD_FAILURE() << "refused though told to go ahead: " << e.what();
  } catch (const std::exception&) {  // no room for the pairing, or no snapshot
  }
  EXPECT_EQ(drawn, 0);
  std::filesystem::remove(huge);
}

TEST(Timelapse, WindHoldsTheYearAndAdvancesTheWindsTime) {
  const RunFolder run = oneTreeRun("timelapse_wind");
  const Terrain terrain = test::flatTerrain(33, 10.0);
  TimelapseSettings settings;
  settings.kind = TimelapseKind::Wind;
  settings.fromYear = settings.toYear = 20.0;
  settings.seconds = 1.0;
  settings.fps = 8;
  settings.camera = [](double) { return Camera{}; };
  Recorded seen;
  const DrawFrame draw = [&](const FrameTrees& trees, const Camera&, const RenderOptions& o) {
    seen.trees.push_back(trees.shown.size());
    seen.windTimes.push_back(o.wind.time);
    // The year's trees indexed once for every frame.
    EXPECT_TRUE(trees.index && trees.index->forestSize() == trees.shown.size());
    return Image(16, 16);
  };
  test::CollectingSink sink;
  renderTimelapse(run, test::smallLibrary(), terrain, draw, settings, sink, {});
  ASSERT_EQ(seen.windTimes.size(), 8u);
  for (std::size_t f = 0; f < 8; ++f) {
    EXPECT_EQ(seen.trees[f], 1u);
    EXPECT_NEAR(seen.windTimes[f], f * settings.windRadiansPerSecond / settings.fps, 1e-12);
  }
}

}  // namespace
}  // namespace eco
