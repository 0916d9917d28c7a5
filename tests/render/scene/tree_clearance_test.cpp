#include "render/scene/tree_clearance.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "render/scene/camera_controller.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// The distance from a point to the nearest LOD0 vertex of any tree, each placed as the
// renderer places it (turned by its yaw, scaled): the trees as drawn, without envelopes.
float nearestVertex(const Forest& forest, const TreeLibrary& library, glm::vec3 point) {
  float nearest = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < forest.size(); ++i) {
    const glm::vec3 base = forest.position[i];
    if (glm::distance(base, point) > 60.0f) continue;
    const float c = std::cos(forest.yaw[i]), s = std::sin(forest.yaw[i]);
    for (const WindPart& part : library.type(forest.type[i]).meshes.lods[0].parts)
      for (const TreeVertex& v : part.vertices) {
        const glm::vec3 scaled(v.position.x * forest.scaleXZ[i], v.position.y * forest.scaleY[i],
                               v.position.z * forest.scaleXZ[i]);
        const glm::vec3 world =
            base + glm::vec3(c * scaled.x - s * scaled.z, scaled.y, s * scaled.x + c * scaled.z);
        nearest = std::min(nearest, glm::distance(world, point));
      }
  }
  return nearest;
}

int matureBeech(const TreeLibrary& library) {
  return library.typeIndex(0, 0, static_cast<int>(library.settings().ageClasses.size()) - 1);
}

TEST(TreeEnvelope, HoldsTheWholeMeshAndIsTheTrunkNearTheGround) {
  const TreeLibrary& library = test::smallLibrary();
  const TreeType& type = library.type(matureBeech(library));
  const float widest = *std::max_element(type.envelope_m.begin(), type.envelope_m.end());
  EXPECT_NEAR(widest, type.crownRadius_m, 0.05f * type.crownRadius_m + 0.05f);
  // The lowest slice is the bole: far narrower than the crown.
  EXPECT_LT(type.envelope_m[0], 0.2f * widest);
  EXPECT_GT(type.envelope_m[0], 0.0f);
}

TEST(TreeClearance, NeverOverstatesTheDistanceToTheTreeAsDrawn) {
  const TreeLibrary& library = test::smallLibrary();
  Forest forest;
  forest.add(library, matureBeech(library), {0, 0, 0}, 25.0f, 6.0f, 1.0f, 11);
  forest.add(library, matureBeech(library), {9, 0, 4}, 18.0f, 4.0f, 1.0f, 12);
  const TreeClearance clearance(forest, library);
  int far = 0;
  for (int k = 0; k < 200; ++k) {
    // Points around and inside both crowns, from the ground to above them.
    const glm::vec3 p(-10.0f + 0.13f * k, 0.5f + 0.14f * k, 8.0f - 0.09f * k);
    const float clear = clearance.at(p, 100.0f);
    EXPECT_LE(clear, nearestVertex(forest, library, p) + 1e-3f) << k;
    if (clear > 1.0f) ++far;
  }
  EXPECT_GT(far, 20);  // not everything is "inside"
  // At eye height beside the trunk the distance is the bole's: the stem's reach away.
  const TreeType& type = library.type(forest.type[0]);
  const glm::vec3 beside(3.0f, 1.7f, 0.0f);
  EXPECT_NEAR(clearance.at(beside, 100.0f), 3.0f - type.envelope_m[1] * forest.scaleXZ[0], 0.1f);
  // Nothing within `beyond`: `beyond` itself.
  EXPECT_FLOAT_EQ(clearance.at({200.0f, 1.7f, 0.0f}, 5.0f), 5.0f);
}

// A dense young stand on flat ground `size_m` across (8 m beeches with branches to eye
// height on a 3 m lattice, each moved up to 1.5 m off it) with one ride running east to
// west at `rideNorth`: the only place where a person stands clear of every tree and sees far.
Forest standWithRide(const TreeLibrary& library, double rideNorth, double size_m = 200.0) {
  Forest forest;
  std::uint64_t id = 0;
  for (double north = 1.5; north < size_m; north += 3.0)
    for (double east = 1.5; east < size_m; east += 3.0) {
      ++id;
      const double jitterEast = 1.5 * std::sin(12.9898 * id),
                   jitterNorth = 1.5 * std::cos(78.233 * id);
      if (std::abs(north + jitterNorth - rideNorth) < 9.0) continue;
      forest.add(library, library.typeIndex(0, 0, 0),
                 glm::vec3(worldFromMap(east + jitterEast, north + jitterNorth, 100.0)), 8.0f, 2.0f,
                 1.0f, id);
    }
  return forest;
}

TEST(GroundCamera, StandsClearOfEveryTrunkAndCrownAndLooksAlongTheRide) {
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(41, 5.0);  // 200 m, level at 100 m
  const Forest forest = standWithRide(library, 140.0);
  const Camera camera = groundCamera(terrain, forest, library);
  EXPECT_GE(nearestVertex(forest, library, camera.position), kGroundClearance_m);
  EXPECT_NEAR(camera.position.y - groundBelow(terrain, camera.position),
              CameraController::kEyeHeight_m, 1e-3f);
  const glm::dvec3 map = mapFromWorld(glm::dvec3(camera.position));
  EXPECT_NEAR(map.y, 140.0, 12.0);  // in the ride or at its edge: the stand is closed
  // Its sight line is open for kGroundView_m.
  EXPECT_GE(openSight(terrain, TreeClearance(forest, library), camera.position,
                      glm::vec3(camera.forward().x, 0, camera.forward().z), kGroundView_m),
            kGroundView_m);
}

// A still's ground camera is placed among the trees near the map's centre only
// (groundCameraMaySee): the same camera as among the whole forest.
TEST(GroundCamera, TheTreesItMaySeePlaceItAsTheWholeForestDoes) {
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(141, 10.0);  // 1.4 km, its centre at 700 m
  const Forest whole = standWithRide(library, 740.0, 1400.0);
  Forest nearCentre;
  for (std::size_t i = 0; i < whole.size(); ++i) {
    const glm::dvec3 map = mapFromWorld(glm::dvec3(whole.position[i]));
    if (groundCameraMaySee(terrain, map.x, map.y)) nearCentre.append(whole, i);
  }
  EXPECT_LT(nearCentre.size(), whole.size() / 2);
  const Camera camera = groundCamera(terrain, whole, library);
  const Camera nearCamera = groundCamera(terrain, nearCentre, library);
  EXPECT_EQ(nearCamera.position, camera.position);
  EXPECT_EQ(nearCamera.yaw_deg, camera.yaw_deg);
  EXPECT_NEAR(mapFromWorld(glm::dvec3(camera.position)).y, 740.0, 12.0);  // in the ride
  // Out to its farthest candidate (300 m), sight line and clearance, and a crown's reach.
  const double reach = 300.0 + kGroundView_m + kGroundClearance_m + kGroundCrownReach_m;
  EXPECT_TRUE(groundCameraMaySee(terrain, 700.0 - reach, 700.0 + reach));
  EXPECT_FALSE(groundCameraMaySee(terrain, 700.0 - reach - 0.1, 700.0));
  EXPECT_FALSE(groundCameraMaySee(terrain, 700.0, 700.0 + reach + 0.1));
}

TEST(GroundCamera, LooksAlongAHillsideRatherThanIntoIt) {
  // A plane rising 20 % to the north: looking north the ground fills the view within a
  // few metres. A sight line 1.7 m up stays half a metre above it for 30 m only where it
  // rises less than 1.2 m over them, 30 m x 0.2 x cos(bearing): beyond 78.5 degrees from
  // north (along the contour or down the slope).
  Terrain terrain = test::flatTerrain(41, 5.0);
  const Grid& g = terrain.grid;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      terrain.height_m[g.index(x, y)] = static_cast<float>(100.0 + 0.2 * g.northOf(y));
  const Camera camera = groundCamera(terrain, Forest{}, test::smallLibrary());
  EXPECT_GE(std::abs(camera.yaw_deg), 78.0f);
  EXPECT_GE(openSight(terrain, TreeClearance(Forest{}, test::smallLibrary()), camera.position,
                      glm::vec3(camera.forward().x, 0, camera.forward().z), kGroundView_m),
            kGroundView_m);
}

TEST(GroundCamera, OnBareGroundStandsAtTheCentreLookingNorth) {
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(41, 5.0);
  const Camera camera = groundCamera(terrain, Forest{}, library);
  const glm::dvec3 map = mapFromWorld(glm::dvec3(camera.position));
  EXPECT_NEAR(map.x, 100.0, 1e-3);
  EXPECT_NEAR(map.y, 100.0, 1e-3);
  EXPECT_FLOAT_EQ(camera.yaw_deg, 0.0f);
}

}  // namespace
}  // namespace eco
