// Sunniness from the sun's path over a year and Embree occlusion rays against the terrain
// (docs/conditions.md). Directions here are (east, north, up) unit vectors.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <numbers>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/terrain.hpp"

namespace eco {

struct SunlightSettings {
  int days = 12;                 // days sampled through the year
  int hoursPerDay = 10;          // sun positions between sunrise and sunset of each day
  int skyDirections = 24;        // directions over the sky hemisphere for the sky-view factor
  double diffuseFraction = 0.4;  // share of diffuse light in annual insolation on open flat ground
};

// Declination (radians) on a day of the year (Cooper 1969).
double solarDeclination(double dayOfYear);
// The hour angle (radians, 0 at solar noon, negative in the morning) of a solar time in
// hours (12 = noon).
constexpr double hourAngleOf(double solarHour) {
  return (solarHour - 12.0) * std::numbers::pi / 12.0;
}
// The unit direction toward the sun at a latitude for a declination and an hour angle
// (radians, 0 at solar noon, negative in the morning).
glm::dvec3 sunDirection(double latitude_deg, double declination, double hourAngle);

// Sun directions above the horizon with weights proportional to the time they stand for
// (declination by Cooper's formula, hour angles spread evenly from sunrise to sunset).
struct SunPath {
  std::vector<glm::dvec3> directions;
  std::vector<double> weights;
};
SunPath makeSunPath(double latitude_deg, const SunlightSettings& settings);

// Directions spread evenly (in solid angle) over the upper hemisphere (a Fibonacci lattice).
std::vector<glm::dvec3> skyDirections(int count);

// The unit normal of a plane of slope and aspect (compass bearing it faces).
glm::dvec3 planeNormal(double slope_deg, double aspect_deg);
// Annual direct-beam insolation on unshaded horizontal ground: sum of weight x sun height.
double flatInsolation(const SunPath& sun);
// Annual direct-beam insolation on an unshaded plane relative to horizontal, for the sun path.
double unshadedDirectRatio(const SunPath& sun, glm::dvec3 normal);

// The terrain's triangles (terrain_mesh.hpp, map frame) as an Embree scene in the one
// Embree device of the process.
class TerrainScene {
 public:
  explicit TerrainScene(const Terrain& terrain);
  ~TerrainScene();
  TerrainScene(const TerrainScene&) = delete;
  TerrainScene& operator=(const TerrainScene&) = delete;

  // For each ray (origin, unit direction, tnear, tfar): is anything in the way?
  struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;
    float tnear = 0.0f, tfar = 0.0f;
  };
  // Casts a batch through rtcOccluded1M; occluded[i] = 1 where ray i is blocked.
  void occluded(const std::vector<Ray>& rays, std::vector<std::uint8_t>& occluded) const;
  // The same rays one by one with rtcOccluded1: the plain reference loop of the benchmark.
  void occludedOneByOne(const std::vector<Ray>& rays, std::vector<std::uint8_t>& occluded) const;

  const Terrain& terrain() const { return terrain_; }
  float cellSize() const {
    return static_cast<float>(std::min(terrain_.grid.dx_m, terrain_.grid.dy_m));
  }
  float maxHeight() const { return maxHeight_m_; }
  float extent() const { return extent_m_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  const Terrain& terrain_;
  float maxHeight_m_ = 0.0f;
  float extent_m_ = 0.0f;
};

// Unit surface normals of the cells of row y.
std::vector<glm::dvec3> rowNormals(const Grid& grid, const Field& slope_deg,
                                   const Field& aspect_deg, int y);
// The rays of one batch: from every cell of row y whose surface faces `direction` (a little
// above it, skipping the first quarter cell so the cell's own facets cannot block it) to
// where the rising ray clears the highest terrain, at most the map's diagonal.
void rowRays(const TerrainScene& scene, int y, const std::vector<glm::dvec3>& normals,
             glm::dvec3 direction, std::vector<TerrainScene::Ray>& rays, std::vector<int>& cells);

struct SunlightParts {
  Field directRelative;  // annual direct beam, shaded, relative to unshaded flat ground
  Field skyView;         // cosine-weighted visible sky, 1 on open flat ground
  double best = 1.0;     // the insolation of the best unshaded slope, relative to flat
  std::uint64_t rays = 0;
};

// sunniness = ((1 - f) direct + f sky) / best, in [0, 1]: 1 is the sunniest unshaded slope
// possible at this latitude, open flat ground is 1 / best.
void computeSunniness(const Terrain& terrain, const Field& slope_deg, const Field& aspect_deg,
                      double latitude_deg, const SunlightSettings& settings, Field& sunniness,
                      SunlightParts* parts = nullptr,
                      const std::function<void(double)>& progress = {});

}  // namespace eco
