#include "sim/conditions/windiness.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "core/frames.hpp"

namespace eco {
namespace {

// Bilinear height at a fractional cell position; false outside the grid.
bool sampleHeight(const Terrain& terrain, double fx, double fy, double& height) {
  const Grid& g = terrain.grid;
  if (fx < 0.0 || fy < 0.0 || fx > g.width - 1.0 || fy > g.height - 1.0) return false;
  int x0 = std::min(static_cast<int>(fx), g.width - 2),
      y0 = std::min(static_cast<int>(fy), g.height - 2);
  double tx = fx - x0, ty = fy - y0;
  double top = terrain.heightAt(x0, y0) * (1.0 - tx) + terrain.heightAt(x0 + 1, y0) * tx;
  double bottom = terrain.heightAt(x0, y0 + 1) * (1.0 - tx) + terrain.heightAt(x0 + 1, y0 + 1) * tx;
  height = top * (1.0 - ty) + bottom * ty;
  return true;
}

}  // namespace

Field upwindSlope(const Terrain& terrain, double from_deg, double searchDistance_m) {
  const Grid& g = terrain.grid;
  const double step_m = std::min(g.dx_m, g.dy_m);
  const int steps = std::max(1, static_cast<int>(searchDistance_m / step_m));
  Field sx(g.cellCount(), 0.0f);
  tbb::parallel_for(0, g.height, [&](int y) {
    for (int x = 0; x < g.width; ++x) {
      const double z0 = terrain.heightAt(x, y);
      double sum = 0.0;
      for (double sector : {-15.0, 0.0, 15.0}) {
        // Upwind, in cells: east is +x, north is -y.
        const glm::dvec2 upwind = mapDirectionOfBearing(from_deg + sector);
        const double ux = upwind.x * step_m / g.dx_m, uy = -upwind.y * step_m / g.dy_m;
        double steepest = -90.0;
        for (int k = 1; k <= steps; ++k) {
          double h;
          if (!sampleHeight(terrain, x + ux * k, y + uy * k, h)) break;
          steepest = std::max(steepest, degrees(std::atan2(h - z0, k * step_m)));
        }
        sum += steepest == -90.0 ? 0.0 : steepest;  // at the upwind edge: nothing known, neutral
      }
      sx[g.index(x, y)] = static_cast<float>(sum / 3.0);
    }
  });
  return sx;
}

Field elevationAngle(const Terrain& terrain, double radius_m) {
  const Grid& g = terrain.grid;
  // A summed-area table gives each cell the mean height of the square around it.
  const int w = g.width, h = g.height;
  std::vector<double> sum(static_cast<std::size_t>(w + 1) * (h + 1), 0.0);
  auto at = [&](int x, int y) -> double& { return sum[static_cast<std::size_t>(y) * (w + 1) + x]; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      at(x + 1, y + 1) = terrain.heightAt(x, y) + at(x, y + 1) + at(x + 1, y) - at(x, y);
  const int rx = std::max(1, static_cast<int>(std::lround(radius_m / g.dx_m)));
  const int ry = std::max(1, static_cast<int>(std::lround(radius_m / g.dy_m)));
  Field angle(g.cellCount());
  tbb::parallel_for(0, h, [&](int y) {
    const int y0 = std::max(0, y - ry), y1 = std::min(h, y + ry + 1);
    for (int x = 0; x < w; ++x) {
      const int x0 = std::max(0, x - rx), x1 = std::min(w, x + rx + 1);
      const double mean = (at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0)) /
                          (static_cast<double>(x1 - x0) * (y1 - y0));
      angle[g.index(x, y)] =
          static_cast<float>(degrees(std::atan((terrain.heightAt(x, y) - mean) / radius_m)));
    }
  });
  return angle;
}

void computeWindiness(const Terrain& terrain, double from_deg, Field& windiness) {
  const Field sx = upwindSlope(terrain, from_deg);
  const Field rise = elevationAngle(terrain, kPositionRadius_m);
  windiness.resize(sx.size());
  for (std::size_t c = 0; c < sx.size(); ++c)
    windiness[c] = static_cast<float>(
        std::clamp(kOpenGroundWindiness + (rise[c] - sx[c]) / kExposureScale_deg, 0.0, 1.0));
}

}  // namespace eco
