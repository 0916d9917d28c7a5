#include "render/gl/scene_renderer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "gl_support.hpp"
#include "render/scene/forest_index.hpp"
#include "render/scene/seen_forest.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// The reference scene: hilly generated terrain, a small grove of beech and maple of both age
// classes, a camera at the edge of the grove, the sun of a June morning.
struct ReferenceScene {
  Terrain terrain;
  Forest forest;
  Camera camera;
  RenderOptions options;
};

ReferenceScene referenceScene() {
  ReferenceScene s;
  s.terrain = generateMidpoint({33, 0.5, 40.0}, 10.0, 10.0, 200.0, 5);
  const TreeLibrary& library = test::smallLibrary();
  for (int i = 0; i < 40; ++i) {
    const double east = 100 + 13.0 * (i % 8) + 3.0 * (i / 8), north = 120 + 14.0 * (i / 8);
    const int type = library.typeIndex(i % 2, 0, (i / 3) % 2);
    const float height = library.type(type).height_m * (0.8f + 0.05f * (i % 5));
    s.forest.add(library, type, worldFromMap(east, north, s.terrain.altitudeAt(east, north)),
                 height, 0.0f, 0.6f + 0.01f * i, static_cast<std::uint64_t>(i));
  }
  s.camera.position = worldFromMap(140, 95, s.terrain.altitudeAt(140, 95) + 4.0);
  s.camera.yaw_deg = 10.0f;
  s.camera.pitch_deg = 12.0f;
  s.options.sun = {172.0, 9.0};
  s.options.wind = {270.0, 1.0, 1.0, 0.25, 0.8};
  return s;
}

// A camera 8 m over the level ground of a 1.27 km stand, looking across it, and a low sun.
Camera overTheStand() {
  return test::cameraAt(worldFromMap(100, 100, 108), 45.0f, -8.0f);
}

RenderOptions morningSun() {
  RenderOptions options;
  options.sun = {160.0, 10.0};
  return options;
}

// A year of a stand on the level ground of test::flatTerrain(129, 10.0) (100 m up): as in a
// forest, most plants young and small, one in fifty a tree of 5 to 30 m.
TreeSnapshot youngStand() {
  TreeSnapshot snapshot;
  snapshot.year = 30;
  snapshot.speciesNames = {"beech", "maple"};
  for (std::uint64_t id = 1; id <= 20000; ++id) {
    TreeRow tree = test::variedTree(id);
    tree.east_m = static_cast<double>((id * 37) % 1270 + 5);
    tree.north_m = static_cast<double>((id * 53 + id / 1270) % 1270 + 5);
    tree.ground_m = 100.0;
    tree.species = static_cast<std::int16_t>(id % 2);
    tree.height_m = id % 50 == 0 ? 5.0f + static_cast<float>(id % 26) : 0.1f + 0.01f * (id % 50);
    tree.crownRadius_m = 0.2f * tree.height_m;
    tree.crownBase_m = 0.3f * tree.height_m;
    snapshot.trees.push_back(tree);
  }
  return snapshot;
}

// With the forest's index a frame looks only at the trees tall enough for a pixel where
// they stand, and is the same frame to the bit, with the same counts.
TEST(SceneRenderer, AForestsIndexDrawsTheSameFrameLookingAtFewerTrees) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(129, 10.0);
  const Forest forest = forestFromSnapshot(youngStand(), library, "stand");
  const ForestIndex index(forest, library);
  SceneRenderer renderer(terrain, 46.0, &library);
  renderer.setForestFloor(forest);
  const Camera camera = overTheStand();
  const RenderOptions options = morningSun();
  const RenderTarget target = RenderTarget::create(160, 90);
  const ForestStats whole = renderer.render(&forest, camera, options, target).forest;
  const Image wholeFrame = readPixels(160, 90);
  const ForestStats indexed = renderer.render(&forest, camera, options, target, &index).forest;
  EXPECT_EQ(readPixels(160, 90).rgba, wholeFrame.rgba);
  EXPECT_EQ(indexed.instances, whole.instances);
  EXPECT_EQ(indexed.culled, whole.culled);
  EXPECT_EQ(indexed.tooSmall, whole.tooSmall);
  EXPECT_EQ(indexed.shadowCasters, whole.shadowCasters);
  EXPECT_EQ(indexed.triangles, whole.triangles);
  EXPECT_EQ(whole.lookedAt, forest.size());
  EXPECT_LT(indexed.lookedAt, forest.size() / 2);
  EXPECT_GT(whole.tooSmall, forest.size() / 2);
  EXPECT_GT(whole.culled, 0u);
}

// A still of a run's year drawn from the trees it can show (forestSeenFrom) on the floor of
// them all is the still of the whole year to the bit, with the same counts.
TEST(SceneRenderer, AStillOfTheTreesItCanShowIsTheStillOfTheWholeYear) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(129, 10.0);
  const TreeSnapshot snapshot = youngStand();
  const RunFolder run = test::runHolding("scene_seen_still", {&snapshot}, SnapshotFormat::Binary);
  const Camera camera = overTheStand();
  const RenderOptions options = morningSun();
  SceneRenderer renderer(terrain, 46.0, &library);
  const RenderTarget target = RenderTarget::create(160, 90);

  const Forest whole = forestFromRun(run, snapshot.year, library);
  renderer.setForestFloor(whole);
  const ForestIndex wholeIndex(whole, library);
  const ForestStats all = renderer.render(&whole, camera, options, target, &wholeIndex).forest;
  const Image wholeFrame = readPixels(160, 90);
  const SeenForest seen =
      forestSeenFrom(run, snapshot.year, library, terrain.grid, camera, {160, 90}, options.lod);
  renderer.setForestFloor(seen.floor);
  const ForestIndex seenIndex(seen.shown, library);
  const ForestStats shown =
      renderer.render(&seen.shown, camera, options, target, &seenIndex).forest;
  EXPECT_EQ(readPixels(160, 90).rgba, wholeFrame.rgba);
  EXPECT_EQ(shown.instances, all.instances);
  EXPECT_EQ(shown.culled + seen.culled, all.culled);
  EXPECT_EQ(shown.tooSmall + seen.tooSmall, all.tooSmall);
  EXPECT_EQ(shown.shadowCasters, all.shadowCasters);
  EXPECT_EQ(shown.triangles, all.triangles);
  EXPECT_LT(seen.shown.size(), whole.size() / 10);
  EXPECT_GT(seen.culled, 0u);
}

Image renderScene(const ReferenceScene& s, int width, int height) {
  SceneRenderer renderer(s.terrain, 46.0, &test::smallLibrary());
  const RenderTarget target = RenderTarget::create(width, height);
  renderer.render(&s.forest, s.camera, s.options, target);
  return readPixels(width, height);
}

// Compared with tests/render/reference/grove.png (ECOFOREST_UPDATE_REFERENCES=1 rewrites it).
// llvmpipe is deterministic on one machine; across CPUs (vector widths) rounding can move
// an alpha-tested leaf edge by a pixel. Tolerances: mean absolute difference at most 1.5 of
// 255 per channel, and no 4x4 block differing by more than 40 on average (a moved leaf edge
// changes single pixels fully, never a whole block).
TEST(SceneRenderer, MatchesTheReferenceImage) {
  test::useHeadlessGl();
  const Image image = renderScene(referenceScene(), 192, 128);
  const std::filesystem::path reference = test::referenceFile("grove.png");
  if (test::updatingReferences()) test::writePng(reference, image);
  const Image expected = test::readPng(reference);
  ASSERT_EQ(expected.width, 192) << "missing " << reference;
  const test::ImageDifference d = test::compareImages(image, expected);
  EXPECT_LE(d.mean, 1.5);
  EXPECT_LE(test::maxBlockDifference(image, expected, 4), 40.0);
  test::writePng(test::freshDirectory("scene") / "grove.png", image);
}

TEST(SceneRenderer, IsDeterministicWhateverTheThreadCount) {
  test::useHeadlessGl();
  const ReferenceScene scene = referenceScene();
  Image one, two;
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
    one = renderScene(scene, 160, 96);
  }
  two = renderScene(scene, 160, 96);
  EXPECT_EQ(test::compareImages(one, two).max, 0);
}

TEST(SceneRenderer, WindTimeMovesTheTreesAndTheSunSetsTheLight) {
  test::useHeadlessGl();
  ReferenceScene scene = referenceScene();
  scene.options.wind = {270.0, 3.0, 3.0, 0.25, 0.8};
  const Image still = renderScene(scene, 160, 96);
  scene.options.wind.time += 1.5;
  const Image later = renderScene(scene, 160, 96);
  EXPECT_GT(test::compareImages(still, later).differingShare, 0.002);
  scene.options.sun.solarHour = 0.0;  // midnight
  const Image night = renderScene(scene, 160, 96);
  EXPECT_LT(test::meanColor(night).g, 0.5f * test::meanColor(still).g);
}

TEST(SceneRenderer, TreesCastShadowsOnTheGround) {
  test::useHeadlessGl();
  ReferenceScene scene = referenceScene();
  const Image shadowed = renderScene(scene, 160, 96);
  scene.options.shadows = false;
  const Image unshadowed = renderScene(scene, 160, 96);
  EXPECT_LT(test::meanColor(shadowed).g, test::meanColor(unshadowed).g);
}

// A single maple planted at year 0 grows through three snapshots; its silhouette in a fixed
// view grows frame after frame (allowing for the dither of age-class blends, and two pixels
// while it is a sprite of ten: the silhouette is the pixels whose colour differs from the
// ground's by more than 8, and a pixel or two of so small a sprite come and go with its
// shading. Measured: 1, 6, 11, 9, 19, 28 ... 168 pixels; 1, 4, 11, 10, 19 ... before the
// impostors' normals were turned by the tree's proportions).
TEST(SceneRenderer, DrawsATimelapseInWhichOneTreesSilhouetteGrows) {
  test::useHeadlessGl();
  const auto dir = test::freshDirectory("timelapse_run");
  std::filesystem::create_directories(dir / "trees");
  const std::string header = std::string(kTreesCsvHeaderWithoutSite) + "\n";
  const std::pair<int, double> sizes[] = {{10, 2.0}, {20, 6.0}, {30, 11.0}};
  RunFolder run;
  run.dir = dir;
  for (auto [year, height] : sizes) {
    test::writeFile(dir / "trees" / fmt::format("year_{:04d}.csv", year),
                    header + fmt::format("1,maple,160,160,100,{},{},{},{},0.1,0.9,1\n", year - 2,
                                         height, 0.3 * height, 0.4 * height));
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
  test::CollectingSink sink;
  const TimelapseTimings t =
      renderTimelapse(run, test::smallLibrary(), terrain, frameDrawer(renderer, settings.frame),
                      settings, sink, {});
  ASSERT_EQ(t.frames, 12);
  ASSERT_EQ(sink.frames.size(), 12u);
  EXPECT_TRUE(sink.finished);
  Forest empty;
  const RenderTarget target = RenderTarget::create(96, 96);
  renderer.render(&empty, settings.camera(0.0), settings.render, target);
  const Image background = readPixels(96, 96);
  const double twoPixels = 2.0 / (96.0 * 96.0);  // of a first silhouette about ten pixels large
  double previous = 0.0;
  for (std::size_t f = 0; f < sink.frames.size(); ++f) {
    const double area = test::compareImages(sink.frames[f], background).differingShare;
    EXPECT_GE(area, previous * 0.95 - twoPixels) << "frame " << f;
    previous = std::max(previous, area);
  }
  EXPECT_GT(previous, 5.0 * test::compareImages(sink.frames[1], background).differingShare);
}

// The haze thins with height (docs/rendering.md, "Light, shadows, sky and fog"): flat ground
// 3 km away seen straight down from 3 km up is hazed far less than the same ground 3 km away
// seen along it, where a haze of uniform density hazes both alike. Measured against the
// ground seen from 200 m up (hazed by under 1 %), as the mean colour of the picture's middle;
// with a scale height of 1.2 km the line down carries 0.37 of the level line's extinction.
// Measured (colour distance, 0..1 a channel): 0.081 down against 0.200 along; with a uniform
// haze 0.205 against 0.206.
TEST(SceneRenderer, HazeThinsWithHeight) {
  test::useHeadlessGl();
  const Terrain terrain = test::flatTerrain(129, 100.0);  // 12.8 km square at 100 m
  SceneRenderer renderer(terrain, 46.0, nullptr);
  const RenderTarget target = RenderTarget::create(64, 64);
  RenderOptions options;
  options.shadows = false;
  auto middleColor = [&](glm::dvec3 at, float pitch_deg) {
    Camera camera;
    camera.position = worldFromMap(at.x, at.y, at.z);
    camera.pitch_deg = pitch_deg;
    camera.fovY_deg = 2.0f;  // the picture's middle: the point 3 km away and its neighbours
    renderer.render(nullptr, camera, options, target);
    const Image image = readPixels(64, 64);
    glm::dvec3 sum(0.0);
    for (int y = 28; y < 36; ++y)
      for (int x = 28; x < 36; ++x) sum += glm::dvec3(glm::vec3(image.get(x, y)));
    return sum / 64.0;
  };
  const glm::dvec3 clear = middleColor({6400, 9400, 300}, -89.0f);
  const glm::dvec3 down = middleColor({6400, 9400, 3100}, -89.0f);
  // 100 m above the ground, looking down to the point 3 km north (1.9 degrees down).
  const float level = -static_cast<float>(degrees(std::atan(100.0 / 3000.0)));
  const glm::dvec3 along = middleColor({6400, 6400, 200}, level);
  const double downHaze = glm::length(down - clear), levelHaze = glm::length(along - clear);
  EXPECT_GT(levelHaze, 0.03) << "the level line is hazed";
  EXPECT_LT(downHaze, 0.5 * levelHaze) << downHaze << " vs " << levelHaze;
}

}  // namespace
}  // namespace eco
