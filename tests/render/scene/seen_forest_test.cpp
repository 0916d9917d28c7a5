#include "render/scene/seen_forest.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "render/scene/camera_path.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

Forest oneTree(float height_m) {
  const TreeLibrary& library = test::smallLibrary();
  const int type = library.typeFor(0, 7, height_m, library.maxHeight_m(0));
  library.build(std::vector<int>{type});
  Forest forest;
  forest.add(library, type, glm::vec3(0.0f), height_m, 0.0f, 1.0f, 7);
  return forest;
}

TEST(SeenForest, ATreeMayBeDrawnWhileItsSphereCentreGivesItMinPixels) {
  const TreeLibrary& library = test::smallLibrary();
  const Forest forest = oneTree(20.0f);
  const TreeType& type = library.type(forest.type[0]);
  const glm::vec3 centre(drawnBounds(forest, 0, type));
  const float height = type.height_m * forest.scaleY[0];
  const float pixelsPerRadian = 1000.0f;
  const LodSettings lod;  // minPixels 1: the tree is a pixel 20 km from its sphere's centre
  const float reach = height * pixelsPerRadian / lod.minPixels;
  auto eyeAt = [&](float distance) { return centre + glm::vec3(0.0f, 0.0f, distance); };
  EXPECT_TRUE(mayBeDrawn(forest, 0, type, eyeAt(0.99f * reach), pixelsPerRadian, lod));
  EXPECT_FALSE(mayBeDrawn(forest, 0, type, eyeAt(1.01f * reach), pixelsPerRadian, lod));
  // From up to 500 m nearer it would be drawn.
  EXPECT_TRUE(mayBeDrawn(forest, 0, type, eyeAt(reach + 400.0f), pixelsPerRadian, lod, 500.0f));
  // Within a thousandth of the size, for the renderer's roundings.
  EXPECT_TRUE(mayBeDrawn(forest, 0, type, eyeAt(1.0005f * reach), pixelsPerRadian, lod));
  // A forced level draws every tree.
  LodSettings forced;
  forced.forcedLevel = 1;
  EXPECT_TRUE(mayBeDrawn(forest, 0, type, eyeAt(100.0f * reach), pixelsPerRadian, forced));
}

TEST(SeenForest, ASumKeepsTheTreesShownInOrderAndTheFloorOfAll) {
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  const Forest whole = demoForest(terrain, library, 400, 3);
  // In two parts, the second starting at tree 150.
  Forest first, second;
  for (std::size_t i = 0; i < whole.size(); ++i) (i < 150 ? first : second).append(whole, i);
  auto verdict = [](std::size_t i) {
    return i % 3 == 0 ? TreeSeen::Shown : i % 3 == 1 ? TreeSeen::Culled : TreeSeen::TooSmall;
  };
  SeenForestSum sum(library, terrain.grid);
  sum.add(first, verdict);
  sum.add(second, [&](std::size_t i) { return verdict(150 + i); });
  const SeenForest seen = std::move(sum).done();

  Forest expected;
  for (std::size_t i = 0; i < whole.size(); i += 3) expected.append(whole, i);
  test::expectSameForest(seen.shown, expected);
  EXPECT_EQ(seen.culled, 133u);
  EXPECT_EQ(seen.tooSmall, 133u);
  const CanopyFloor floor = canopyFloor(whole, library, terrain.grid);
  EXPECT_EQ(seen.floor.crownsBelow, floor.crownsBelow);
  EXPECT_EQ(seen.floor.leafColor, floor.leafColor);
}

// More trees than a batch of the snapshot's reading, over 1 km, most of them young plants.
TreeSnapshot forestOfYoungPlants() {
  TreeSnapshot snapshot;
  snapshot.year = 10;
  snapshot.speciesNames = {"beech"};
  for (std::uint64_t id = 1; id <= (std::uint64_t{1} << 20) + 3000; ++id)
    snapshot.trees.push_back(test::mostlyYoungTree(id));
  return snapshot;
}

TEST(SeenForest, AStillOfARunKeepsTheTreesItCanShowAndCountsTheOthers) {
  const TreeLibrary& library = test::smallLibrary();
  const TreeSnapshot snapshot = forestOfYoungPlants();
  const RunFolder run = test::runHolding("seen_forest", {&snapshot}, SnapshotFormat::Binary);
  const Terrain terrain = test::flatTerrain(106, 10.0);
  const FrameSize frame{640, 360};
  const Camera camera = lookingAt(worldFromMap(0, 0, 420), worldFromMap(500, 500, 300));
  const LodSettings lod;
  const SeenForest seen =
      forestSeenFrom(run, snapshot.year, library, terrain.grid, camera, frame, lod);

  const Forest whole = forestFromRun(run, snapshot.year, library);
  const CanopyFloor floor = canopyFloor(whole, library, terrain.grid);
  EXPECT_EQ(seen.floor.crownsBelow, floor.crownsBelow);
  EXPECT_EQ(seen.floor.leafColor, floor.leafColor);
  // The trees shown are the whole forest's in its order, less those under a pixel as the
  // renderer measures them; those are counted by where they stand.
  const Frustum frustum = Frustum::fromMatrix(camera.projection(640.0f / 360.0f) * camera.view());
  const float pixelsPerRadian = camera.pixelsPerRadian(frame.height);
  std::size_t drawn = 0, next = 0, culled = 0, tooSmall = 0;
  Forest expected;
  for (std::size_t i = 0; i < whole.size(); ++i) {
    const TreeType& type = library.type(whole.type[i]);
    const glm::vec4 bounds = drawnBounds(whole, i, type);
    const float distance = glm::length(glm::vec3(bounds) - camera.position);
    const bool shown = next < seen.shown.size() && seen.shown.position[next] == whole.position[i];
    if (shown) {
      ++next;
      expected.append(whole, i);
    } else {
      EXPECT_TRUE(tooSmallToDraw(
          projectedPixels(type.height_m * whole.scaleY[i], distance, pixelsPerRadian), lod))
          << "tree " << i << " is drawn from the camera";
      ++(frustum.intersectsSphere(glm::vec3(bounds), bounds.w) ? tooSmall : culled);
    }
    drawn += shown;
  }
  EXPECT_EQ(next, seen.shown.size());  // in order, nothing else
  test::expectSameForest(seen.shown, expected);
  EXPECT_EQ(seen.culled, culled);
  EXPECT_EQ(seen.tooSmall, tooSmall);
  EXPECT_GT(culled, 1000u);  // behind the camera, beside the view
  EXPECT_GT(drawn, 1000u);
  EXPECT_LT(drawn, whole.size() / 2);
}

TEST(SeenForest, AWholeForestIsShownOnItsFloor) {
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  const Forest forest = demoForest(terrain, library, 50, 3);
  const SeenForest seen = wholeForest(forest, library, terrain.grid);
  test::expectSameForest(seen.shown, forest);
  EXPECT_EQ(seen.culled + seen.tooSmall, 0u);
  EXPECT_EQ(seen.floor.crownsBelow, canopyFloor(forest, library, terrain.grid).crownsBelow);
}

}  // namespace
}  // namespace eco
