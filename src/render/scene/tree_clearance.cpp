#include "render/scene/tree_clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/angles.hpp"
#include "render/scene/camera_controller.hpp"

namespace eco {
float drawnReach_m(const Forest& forest, std::size_t i, const TreeLibrary& library) {
  const TreeType& type = library.type(forest.type[i]);
  return *std::max_element(type.envelope_m.begin(), type.envelope_m.end()) * forest.scaleXZ[i];
}

TreeClearance::TreeClearance(const Forest& forest, const TreeLibrary& library)
    : forest_(forest), library_(library) {
  if (forest.size() == 0) return;
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (std::size_t i = 0; i < forest.size(); ++i) {
    const glm::vec2 p(forest.position[i].x, forest.position[i].z);
    lo = glm::min(lo, p), hi = glm::max(hi, p);
    maxReach_m_ = std::max(maxReach_m_, drawnReach_m(forest, i, library));
  }
  origin_ = lo;
  columns_ = static_cast<int>((hi.x - lo.x) / kCell_m) + 1;
  rows_ = static_cast<int>((hi.y - lo.y) / kCell_m) + 1;
  auto cellOf = [&](std::size_t i) {
    const int cx = static_cast<int>((forest.position[i].x - origin_.x) / kCell_m);
    const int cz = static_cast<int>((forest.position[i].z - origin_.y) / kCell_m);
    return static_cast<std::size_t>(cz) * columns_ + cx;
  };
  // Counting sort by cell: trees keep their order within a cell.
  cellStart_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (std::size_t i = 0; i < forest.size(); ++i) ++cellStart_[cellOf(i) + 1];
  for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  order_.resize(forest.size());
  std::vector<std::uint32_t> next(cellStart_.begin(), cellStart_.end() - 1);
  for (std::size_t i = 0; i < forest.size(); ++i)
    order_[next[cellOf(i)]++] = static_cast<std::uint32_t>(i);
}

float TreeClearance::distanceTo(std::size_t i, glm::vec3 point) const {
  const TreeType& type = library_.type(forest_.type[i]);
  const glm::vec3 base = forest_.position[i];
  const float horizontal = std::hypot(point.x - base.x, point.z - base.z);
  const float sliceHeight = type.height_m * forest_.scaleY[i] / TreeType::kEnvelopeBins;
  float nearest = std::numeric_limits<float>::max();
  for (int b = 0; b < TreeType::kEnvelopeBins; ++b) {
    const float reach = type.envelope_m[b] * forest_.scaleXZ[i];
    if (reach <= 0.0f) continue;
    const float bottom = base.y + b * sliceHeight, top = bottom + sliceHeight;
    const float dy = std::max({bottom - point.y, point.y - top, 0.0f});
    const float dr = std::max(horizontal - reach, 0.0f);
    nearest = std::min(nearest, std::hypot(dr, dy));
  }
  return nearest;
}

float TreeClearance::at(glm::vec3 point, float beyond) const {
  if (order_.empty()) return beyond;
  const float search = beyond + maxReach_m_;
  const int x0 =
      std::max(0, static_cast<int>(std::floor((point.x - search - origin_.x) / kCell_m)));
  const int x1 = std::min(columns_ - 1,
                          static_cast<int>(std::floor((point.x + search - origin_.x) / kCell_m)));
  const int z0 =
      std::max(0, static_cast<int>(std::floor((point.z - search - origin_.y) / kCell_m)));
  const int z1 =
      std::min(rows_ - 1, static_cast<int>(std::floor((point.z + search - origin_.y) / kCell_m)));
  float nearest = beyond;
  for (int cz = z0; cz <= z1; ++cz)
    for (int cx = x0; cx <= x1; ++cx) {
      const std::size_t c = static_cast<std::size_t>(cz) * columns_ + cx;
      for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k)
        nearest = std::min(nearest, distanceTo(order_[k], point));
    }
  return nearest;
}

Camera clearOfTrees(Camera camera, const TreeClearance& trees) {
  constexpr float kStep_m = 0.5f;
  for (float lift = 0.0f; lift < kMaxLift_m; lift += kStep_m) {
    if (trees.at(camera.position, kGroundClearance_m) >= kGroundClearance_m) break;
    camera.position.y += kStep_m;
  }
  return camera;
}

float openSight(const Terrain& terrain, const TreeClearance& trees, glm::vec3 eye,
                glm::vec3 direction, float max_m) {
  constexpr float kStep_m = 0.5f, kMargin_m = 0.5f;
  for (float s = kStep_m; s <= max_m; s += kStep_m) {
    const glm::vec3 p = eye + s * direction;
    if (p.y < groundBelow(terrain, p) + kMargin_m || trees.at(p, kMargin_m) < kMargin_m)
      return s - kStep_m;
  }
  return max_m;
}

namespace {

// groundCamera's candidates: on a 2 m lattice in square rings around the map's centre, out to
// 300 m or `kMargin_m` from its nearer edge.
struct GroundSearch {
  static constexpr double kStep_m = 2.0, kMaxDistance_m = 300.0, kMargin_m = 10.0;
  double centreEast = 0.0, centreNorth = 0.0;
  int rings = 0;

  explicit GroundSearch(const Grid& g) {
    const double width = g.eastOf(g.width - 1), depth = g.northOf(0);
    centreEast = 0.5 * width, centreNorth = 0.5 * depth;
    rings = std::max(
        0, static_cast<int>(std::min(kMaxDistance_m, 0.5 * std::min(width, depth) - kMargin_m) /
                            kStep_m));
  }
};

}  // namespace

bool groundCameraMaySee(const Terrain& terrain, double east, double north) {
  const GroundSearch search(terrain.grid);
  const double reach = search.rings * GroundSearch::kStep_m + kGroundView_m + kGroundClearance_m +
                       kGroundCrownReach_m;
  return std::abs(east - search.centreEast) <= reach &&
         std::abs(north - search.centreNorth) <= reach;
}

Camera groundCamera(const Terrain& terrain, const Forest& forest, const TreeLibrary& library) {
  const GroundSearch search(terrain.grid);
  const TreeClearance clearance(forest, library);
  const float eye = CameraController::kEyeHeight_m;
  auto eyeAt = [&](double east, double north) {
    return worldFromMap(east, north, terrain.altitudeAt(east, north) + eye);
  };

  // The most open bearing from a point: the longest free sight line at eye height, the one
  // nearest north among equally long ones (bearings in steps of 5 degrees, both ways).
  struct Sight {
    float bearing_deg = 0.0f, free_m = -1.0f;
  };
  auto mostOpen = [&](glm::vec3 position) {
    Sight best;
    for (int k = 0; k <= 36; ++k)
      for (int sign : {1, -1}) {
        if (sign < 0 && (k == 0 || k == 36)) continue;
        const float bearing = static_cast<float>(sign * 5 * k);
        const glm::vec3 direction(worldDirectionOfBearing(bearing));
        const float free = openSight(terrain, clearance, position, direction, kGroundView_m);
        if (free > best.free_m) best = {bearing, free};
      }
    return best;
  };

  // Candidates in rings of growing distance from the centre. The fallback is the best point
  // seen: the clearest, then the most open.
  Camera camera;
  camera.near_m = 0.1f;
  float bestClear = -1.0f, bestFree = -1.0f;
  auto consider = [&](int i, int j) {
    const double east = search.centreEast + i * GroundSearch::kStep_m;
    const double north = search.centreNorth + j * GroundSearch::kStep_m;
    const glm::vec3 position = eyeAt(east, north);
    const float clear = clearance.at(position, kGroundClearance_m);
    if (clear < bestClear) return false;
    const Sight sight = mostOpen(position);
    if (clear > bestClear || sight.free_m > bestFree) {
      bestClear = clear, bestFree = sight.free_m;
      camera.position = position;
      camera.yaw_deg = sight.bearing_deg;
    }
    return clear >= kGroundClearance_m && sight.free_m >= kGroundView_m;
  };
  if (consider(0, 0)) return camera;
  for (int r = 1; r <= search.rings; ++r) {
    for (int i = -r; i <= r; ++i)
      if (consider(i, -r) || consider(i, r)) return camera;
    for (int j = -r + 1; j < r; ++j)
      if (consider(-r, j) || consider(r, j)) return camera;
  }
  return camera;
}

}  // namespace eco
