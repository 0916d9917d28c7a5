// Camera paths for time-lapses: an orbit around the map's centre, a flyover along it, or
// keyframes from a small TOML file (docs/rendering.md), interpolated with Catmull-Rom splines
// and kept above the terrain.
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

#include <glm/vec3.hpp>

#include "render/scene/camera.hpp"
#include "sim/terrain.hpp"

namespace eco {

// Where the camera is at u in [0, 1] of the animation.
using CameraPath = std::function<Camera(double u)>;

inline constexpr double kCameraClearance_m = 2.0;  // least height above the ground

// Once around the map's centre, looking at it from 35 degrees above, starting from the south
// (never lower than kCameraClearance_m above the ground under it).
CameraPath orbitPath(const Terrain& terrain);
// From the map's south edge to its north edge along its middle, 80 m above the highest
// ground within 200 m ahead, looking north 15 degrees down.
CameraPath flyoverPath(const Terrain& terrain);

struct CameraKey {
  double time = 0.0;         // any unit; the keys span the animation
  glm::vec3 position{0.0f};  // world frame (worldFromMap of the file's east, north, altitude)
  glm::vec3 lookAt{0.0f};
};
// Catmull-Rom through the keys (the end keys repeated), never below the ground plus
// kCameraClearance_m. Keys must have increasing times.
CameraPath keyframePath(std::vector<CameraKey> keys, const Terrain& terrain);
// [[key]] tables with time, position = [east, north, altitude] and look_at = [...]; at least
// two, with increasing times. Errors name the file, line and key.
CameraPath loadCameraPath(const std::filesystem::path& file, const Terrain& terrain);

// The camera at `position` looking at `target`.
Camera lookingAt(glm::vec3 position, glm::vec3 target);

}  // namespace eco
