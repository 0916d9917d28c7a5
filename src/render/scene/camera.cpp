#include "render/scene/camera.hpp"

#include "core/angles.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace eco {

float groundBelow(const Terrain& terrain, glm::vec3 world) {
  const glm::dvec3 map = mapFromWorld(world);
  return terrain.altitudeAt(map.x, map.y);
}

glm::vec3 Camera::forward() const {
  const float yaw = radians(yaw_deg), pitch = radians(pitch_deg);
  return {std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::vec3 Camera::right() const {
  const float yaw = radians(yaw_deg);
  return {std::cos(yaw), 0.0f, std::sin(yaw)};
}

glm::mat4 Camera::view() const {
  // Straight up or down the world's up is the view axis; the yaw's heading is "up" instead.
  const glm::vec3 up = std::abs(pitch_deg) > 89.9f ? glm::vec3(std::sin(radians(yaw_deg)), 0.0f,
                                                               -std::cos(radians(yaw_deg)))
                                                   : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::lookAt(position, position + forward(), up);
}

glm::mat4 Camera::projection(float aspect) const {
  return glm::perspective(radians(fovY_deg), aspect, near_m, far_m);
}

float Camera::pixelsPerRadian(int viewportHeight) const {
  return 0.5f * static_cast<float>(viewportHeight) / std::tan(0.5f * radians(fovY_deg));
}

std::optional<Camera> parseCamera(const std::string& text) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
    values.push_back(v);
  }
  if (values.size() != 5 || values[4] < -90.0 || values[4] > 90.0) return std::nullopt;
  Camera camera;
  camera.position = worldFromMap(values[0], values[1], values[2]);
  camera.yaw_deg = static_cast<float>(values[3]);
  camera.pitch_deg = static_cast<float>(values[4]);
  return camera;
}

Camera presetCamera(CameraPreset preset, const Terrain& terrain) {
  const Grid& g = terrain.grid;
  const double east = g.eastOf(g.width - 1) * 0.5, north = g.northOf(0) * 0.5;
  const FieldStats heights = statsOf(terrain.height_m);
  Camera camera;
  if (preset == CameraPreset::Low) {
    const double south = g.northOf(0) / 6.0;
    camera.position = worldFromMap(east, south, terrain.altitudeAt(east, south) + 60.0);
    camera.pitch_deg = -12.0f;
    return camera;
  }
  if (preset == CameraPreset::Ground) {
    camera.position = worldFromMap(east, north, terrain.altitudeAt(east, north) + 1.7);
    camera.near_m = 0.1f;
    return camera;
  }
  // Looking down 35 degrees from the south; the distance fits the map's diagonal into the
  // vertical field of view.
  const double size = std::hypot(g.eastOf(g.width - 1), g.northOf(0));
  const double pitch = radians(35.0);
  const double distance = 0.36 * size / std::tan(0.5 * radians(camera.fovY_deg));
  camera.pitch_deg = -35.0f;
  camera.yaw_deg = 0.0f;
  camera.position = worldFromMap(east, north - distance * std::cos(pitch),
                                 heights.mean + distance * std::sin(pitch));
  camera.near_m = 2.0f;
  return camera;
}

}  // namespace eco
