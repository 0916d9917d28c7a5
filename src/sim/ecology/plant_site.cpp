#include "sim/ecology/plant_site.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <tbb/parallel_for.h>

#include "core/angles.hpp"
#include "core/frames.hpp"
#include "sim/conditions/windiness.hpp"

namespace eco {

namespace {

constexpr int kDirections = 8;

std::array<glm::dvec2, kDirections> sampleDirections() {
  std::array<glm::dvec2, kDirections> d{};
  for (int k = 0; k < kDirections; ++k)
    d[k] = {std::cos(2.0 * kPi * k / kDirections), std::sin(2.0 * kPi * k / kDirections)};
  return d;
}

}  // namespace

glm::dvec2 lightDirection(const LightGrid& light, double east_m, double north_m,
                          double crownRadius_m, double crownBase_m, double height_m) {
  static const std::array<glm::dvec2, kDirections> directions = sampleDirections();
  const double reach = LightGrid::beyondCrown_m(crownRadius_m);
  const double height = 0.5 * (crownBase_m + height_m);
  glm::dvec2 sum(0.0);
  double total = 0.0;
  for (const glm::dvec2& d : directions) {
    const double l = light.lightAt(east_m + reach * d.x, north_m + reach * d.y, height);
    sum += l * d;
    total += l;
  }
  return total > 0.0 ? sum / total : glm::dvec2(0.0);
}

double windExposure(double windiness) {
  if (!std::isfinite(windiness)) return 0.0;
  return std::clamp((windiness - kOpenGroundWindiness) / (1.0 - kOpenGroundWindiness), 0.0, 1.0);
}

PlantSite plantSite(const Plants& p, std::size_t i, const LightGrid& light, const Grid& grid,
                    const Field& windiness, glm::dvec2 downwind) {
  if (p.height_m[i] < kShapedFromHeight_m) return {};
  const long cell = grid.cellAt(p.east_m[i], p.north_m[i]);
  const double exposure = cell < 0 ? 0.0 : windExposure(windiness[static_cast<std::size_t>(cell)]);
  PlantSite site;
  site.wind = glm::vec2(exposure * downwind);
  site.light = glm::vec2(lightDirection(light, p.east_m[i], p.north_m[i], p.crownRadius_m[i],
                                        p.crownBase_m[i], p.height_m[i]));
  return site;
}

std::vector<PlantSite> plantSites(const Plants& p, const LightGrid& light, const Grid& grid,
                                  const Field& windiness, double windFrom_deg) {
  const glm::dvec2 downwind = mapDownwindOf(windFrom_deg);
  std::vector<PlantSite> sites(p.size());
  tbb::parallel_for(std::size_t{0}, p.size(), [&](std::size_t i) {
    sites[i] = plantSite(p, i, light, grid, windiness, downwind);
  });
  return sites;
}

}  // namespace eco
