// Living conditions of a 1025 x 1025 midpoint-displacement terrain (10 m cells): time per
// field, sun rays per second, and as reference a plain Embree loop (rtcOccluded1 per ray)
// over the same rays and scene. Goals: the sunlight pass reaches >= 80% of the plain loop's
// rays/s, and the whole run takes < 20 s on the 2-core machine.
// Usage: conditions_bench [cells per side = 2^n + 1, default 1025]
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include <tbb/parallel_for.h>

#include "sim/conditions/conditions.hpp"
#include "sim/conditions/slope.hpp"

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  const int size = argc > 1 ? std::atoi(argv[1]) : 1025;
  eco::Terrain terrain = eco::generateMidpoint({size, 0.55, 800.0}, 10.0, 10.0, 300.0, 42);
  eco::Climate climate;
  eco::SunlightSettings sunlight;

  auto start = Clock::now();
  eco::ConditionsReport report;
  eco::ConditionFields fields = eco::computeConditions(terrain, climate, sunlight, &report);
  const double totalS = std::chrono::duration<double>(Clock::now() - start).count();
  std::printf("conditions of %d x %d cells: %.2f s in all\n", size, size, totalS);
  for (const auto& [name, ms] : report.fieldMilliseconds)
    std::printf("  %-10s %9.1f ms\n", name.c_str(), ms);
  std::printf("  sunlight pass: %.1f M rays, %.2f M rays/s\n", report.sunRays / 1e6,
              report.sunRaysPerSecond / 1e6);

  // The reference: the same rays (same construction, same scene), one rtcOccluded1 each.
  eco::TerrainScene scene(terrain);
  eco::SunPath sun = eco::makeSunPath(climate.latitude_deg, sunlight);
  std::vector<glm::dvec3> directions = sun.directions;
  for (const glm::dvec3& d : eco::skyDirections(sunlight.skyDirections)) directions.push_back(d);
  std::atomic<std::uint64_t> rays{0}, blockedCount{0};
  auto referenceStart = Clock::now();
  tbb::parallel_for(0, terrain.grid.height, [&](int y) {
    std::vector<eco::TerrainScene::Ray> batch;
    std::vector<int> cells;
    std::vector<std::uint8_t> blocked;
    auto normals = eco::rowNormals(terrain.grid, fields.slope_deg, fields.aspect_deg, y);
    for (const glm::dvec3& d : directions) {
      eco::rowRays(scene, y, normals, d, batch, cells);
      scene.occludedOneByOne(batch, blocked);
      rays += batch.size();
      for (std::uint8_t b : blocked) blockedCount += b;
    }
  });
  const double referenceS = std::chrono::duration<double>(Clock::now() - referenceStart).count();
  const double referenceRate = rays / referenceS;
  std::printf("  plain Embree loop: %.1f M rays, %.2f M rays/s (%.1f%% blocked)\n", rays / 1e6,
              referenceRate / 1e6, 100.0 * blockedCount / std::max<std::uint64_t>(rays, 1));
  std::printf("goal: sunlight pass / plain loop = %.0f%% (>= 80%%), whole run %.2f s (< 20 s)\n",
              100.0 * report.sunRaysPerSecond / referenceRate, totalS);
  return rays == report.sunRays ? 0 : 1;  // the two passes must cast the same rays
}
