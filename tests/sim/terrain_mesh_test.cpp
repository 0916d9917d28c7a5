#include "sim/terrain_mesh.hpp"

#include <embree3/rtcore.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/random.hpp"
#include "sim/embree_device.hpp"
#include "sim/scenario.hpp"
#include "terrain_support.hpp"

namespace eco {
namespace {

Terrain hills() {
  // Rough midpoint relief on non-square cells: steep enough that any disagreement between
  // two triangulations of a square shows by metres.
  return generateMidpoint({.size = 33, .roughness = 0.7, .relief_m = 300.0}, 10.0, 7.0, 400.0, 3);
}

// The altitude where a vertical ray from high above (east, north) first meets `scene`.
float embreeAltitude(RTCScene scene, double east, double north) {
  RTCRayHit hit{};
  hit.ray.org_x = static_cast<float>(east), hit.ray.org_y = static_cast<float>(north);
  hit.ray.org_z = 5000.0f;
  hit.ray.dir_z = -1.0f;
  hit.ray.tfar = 1e5f;
  hit.ray.mask = 0xFFFFFFFFu;
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene, &context, &hit);
  EXPECT_NE(hit.hit.geomID, RTC_INVALID_GEOMETRY_ID) << "no hit at " << east << ", " << north;
  return 5000.0f - hit.ray.tfar;
}

TEST(TerrainMesh, AltitudeAtIsWhereARayMeetsTheEmbreeTerrainEverywhere) {
  const Terrain terrain = hills();
  const Grid& g = terrain.grid;
  RTCScene scene = rtcNewScene(embree().device);
  RTCGeometry mesh = newTerrainGeometry(terrain);
  rtcAttachGeometry(scene, mesh);
  rtcReleaseGeometry(mesh);
  rtcCommitScene(scene);
  embree().check("the test scene");
  // Random points, and points on the cell centres, edges and diagonals of every square.
  Rng rng(streamKey(11, purpose("test.terrain")));
  std::vector<glm::dvec2> points;
  for (int i = 0; i < 20000; ++i)
    points.emplace_back(rng.uniform(0.0, g.eastOf(g.width - 1)), rng.uniform(0.0, g.northOf(0)));
  for (int y = 0; y + 1 < g.height; ++y)
    for (int x = 0; x + 1 < g.width; ++x)
      for (auto [fx, fy] : {std::pair{0.5, 0.5},
                            {0.25, 0.25},
                            {0.75, 0.75},
                            {0.5, 0.0},
                            {0.0, 0.5},
                            {0.9, 0.3},
                            {0.1, 0.6}})
        points.emplace_back(g.eastOf(x) + fx * g.dx_m, g.northOf(y) - fy * g.dy_m);
  double worst = 0.0;
  for (const glm::dvec2 p : points) {
    // The outer border of the mesh is where a vertical ray may graze past it.
    if (p.x <= 0.0 || p.y <= 0.0 || p.x >= g.eastOf(g.width - 1) || p.y >= g.northOf(0)) continue;
    worst = std::max(worst, std::abs(static_cast<double>(embreeAltitude(scene, p.x, p.y)) -
                                     terrain.altitudeAt(p.x, p.y)));
  }
  rtcReleaseScene(scene);
  // Float vertices around 500 m and Embree's float intersection: a few millimetres at most.
  EXPECT_LT(worst, 5e-3) << "over " << points.size() << " points";
}

TEST(TerrainMesh, TwoTrianglesPerSquareFacingUpAndMeetingAtTheCellCentres) {
  const Terrain terrain = hills();
  const Grid& g = terrain.grid;
  const std::vector<std::uint32_t> triangles = terrainTriangles(g);
  ASSERT_EQ(triangles.size(), 6u * (g.width - 1) * (g.height - 1));
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    auto position = [&](std::uint32_t cell) {
      return cellPosition(terrain, static_cast<int>(cell % g.width),
                          static_cast<int>(cell / g.width));
    };
    const glm::vec3 a = position(triangles[t]), b = position(triangles[t + 1]),
                    c = position(triangles[t + 2]);
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f) << "triangle " << t / 3 << " faces down";
  }
  // At a cell centre every triangulation agrees: the cell's own height.
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      EXPECT_FLOAT_EQ(terrain.altitudeAt(g.eastOf(x), g.northOf(y)), terrain.heightAt(x, y));
}

// The rim: a strip of half a cell on each side and a square at each corner, facing up,
// out to the cells' outer edges exactly, where it lies on the triangles' flat continuation
// (altitudeAt), so that the plants of edge cells stand on what is drawn.
TEST(TerrainMesh, TheRimCoversEveryCellOnTheFlatContinuation) {
  const Terrain terrain = hills();
  const Grid& g = terrain.grid;
  const TerrainRim rim = terrainRim(g);
  EXPECT_EQ(rim.vertices.size(), 2u * g.width + 2u * g.height + 4u);
  EXPECT_EQ(rim.triangles.size(), 6u * (2 * (g.width - 1) + 2 * (g.height - 1) + 4));
  auto position = [&](std::uint32_t i) {
    return i < g.cellCount()
               ? cellPosition(terrain, static_cast<int>(i % g.width), static_cast<int>(i / g.width))
               : rim.vertices[i - g.cellCount()].position(terrain);
  };
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (std::size_t t = 0; t < rim.triangles.size(); t += 3) {
    const glm::vec3 a = position(rim.triangles[t]), b = position(rim.triangles[t + 1]),
                    c = position(rim.triangles[t + 2]);
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f) << "rim triangle " << t / 3 << " faces down";
    for (const glm::vec3& p : {a, b, c}) {
      lo = glm::min(lo, glm::vec2(p));
      hi = glm::max(hi, glm::vec2(p));
      EXPECT_FLOAT_EQ(terrain.altitudeAt(p.x, p.y), p.z);
    }
  }
  EXPECT_FLOAT_EQ(lo.x, static_cast<float>(-0.5 * g.dx_m));
  EXPECT_FLOAT_EQ(lo.y, static_cast<float>(-0.5 * g.dy_m));
  EXPECT_FLOAT_EQ(hi.x, static_cast<float>(g.eastOf(g.width - 1) + 0.5 * g.dx_m));
  EXPECT_FLOAT_EQ(hi.y, static_cast<float>(g.northOf(0) + 0.5 * g.dy_m));
  // Its map coordinates reach the texture's edges.
  EXPECT_FLOAT_EQ(rim.vertices.back().mapUv(g).x, 1.0f);  // the south-east corner
  EXPECT_FLOAT_EQ(rim.vertices.back().mapUv(g).y, 1.0f);
}

TEST(TerrainMesh, TheSquaresSplitAlongTheNorthEastToSouthWestDiagonal) {
  const Grid g{3, 3, 1.0, 1.0};
  // Square (0, 0): NW = 0, NE = 1, SW = 3, SE = 4; both triangles share NE and SW.
  EXPECT_EQ(squareTriangles(g, 0, 0), (std::array<std::uint32_t, 6>{0, 3, 1, 1, 3, 4}));
}

TEST(TerrainMesh, NormalsOfPlanesAreExactEvenAtTheEdges) {
  Terrain terrain = test::analyticTerrain(9, 9, 10, 10, [](double, double) { return 100.0; });
  EXPECT_EQ(terrainNormal(terrain, 0, 0), glm::dvec3(0, 0, 1));
  // Rising 1 m per 2 m eastward (26.6 degrees): the normal leans west.
  terrain = test::analyticTerrain(9, 9, 10, 10, [](double east, double) { return 0.5 * east; });
  const glm::dvec3 expected = glm::normalize(glm::dvec3(-0.5, 0.0, 1.0));
  for (int x : {0, 4, 8})
    for (int y : {0, 3, 8}) EXPECT_LT(glm::distance(terrainNormal(terrain, x, y), expected), 1e-12);
  // Falling toward the north on non-square cells: the normal leans north.
  terrain = test::analyticTerrain(9, 9, 10, 30, [](double, double north) { return 0.25 * north; });
  EXPECT_LT(
      glm::distance(terrainNormal(terrain, 8, 0), glm::normalize(glm::dvec3(0.0, -0.25, 1.0))),
      1e-12);
}

}  // namespace
}  // namespace eco
