#include "render/scene/camera_path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/frames.hpp"
#include "core/toml_reader.hpp"

namespace eco {
namespace {

glm::vec3 catmullRom(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, float t) {
  const float t2 = t * t, t3 = t2 * t;
  return 0.5f * (2.0f * p1 + (p2 - p0) * t + (2.0f * p0 - 5.0f * p1 + 4.0f * p2 - p3) * t2 +
                 (3.0f * p1 - p0 - 3.0f * p2 + p3) * t3);
}

glm::vec3 mapCentre(const Terrain& terrain) {
  const Grid& g = terrain.grid;
  const double east = 0.5 * g.eastOf(g.width - 1), north = 0.5 * g.northOf(0);
  return worldFromMap(east, north, terrain.altitudeAt(east, north));
}

}  // namespace

Camera lookingAt(glm::vec3 position, glm::vec3 target) {
  Camera camera;
  camera.position = position;
  const glm::vec3 d = glm::normalize(target - position);
  camera.yaw_deg = bearingOfWorldDirection(d);
  camera.pitch_deg = degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
  return camera;
}

CameraPath orbitPath(const Terrain& terrain) {
  const Grid& g = terrain.grid;
  const glm::vec3 centre = mapCentre(terrain);
  const float radius = 0.45f * static_cast<float>(std::hypot(g.eastOf(g.width - 1), g.northOf(0)));
  const float height = radius * std::tan(radians(35.0f));
  return [=, &terrain](double u) {
    const double angle = 2.0 * std::numbers::pi * u;
    // From the south (+z), turning counter-clockwise seen from above; over a hill higher than
    // the orbit the camera rises above it.
    glm::vec3 position =
        centre + glm::vec3(radius * std::sin(angle), height, radius * std::cos(angle));
    position.y = std::max(position.y,
                          groundBelow(terrain, position) + static_cast<float>(kCameraClearance_m));
    return lookingAt(position, centre);
  };
}

CameraPath flyoverPath(const Terrain& terrain) {
  const Grid& g = terrain.grid;
  const double east = 0.5 * g.eastOf(g.width - 1), length = g.northOf(0);
  return [=, &terrain](double u) {
    const double north = u * length;
    double highest = terrain.altitudeAt(east, north);
    for (double ahead = 0.0; ahead <= 200.0; ahead += 10.0)
      highest =
          std::max<double>(highest, terrain.altitudeAt(east, std::min(north + ahead, length)));
    Camera camera;
    camera.position = worldFromMap(east, north, highest + 80.0);
    camera.yaw_deg = 0.0f;
    camera.pitch_deg = -15.0f;
    return camera;
  };
}

CameraPath keyframePath(std::vector<CameraKey> keys, const Terrain& terrain) {
  return [keys = std::move(keys), &terrain](double u) {
    const double time =
        keys.front().time + std::clamp(u, 0.0, 1.0) * (keys.back().time - keys.front().time);
    std::size_t k = 0;
    while (k + 2 < keys.size() && keys[k + 1].time <= time) ++k;
    const CameraKey& a = keys[k];
    const CameraKey& b = keys[k + 1];
    const CameraKey& before = keys[k == 0 ? 0 : k - 1];
    const CameraKey& after = keys[std::min(k + 2, keys.size() - 1)];
    const float t = static_cast<float>(std::clamp((time - a.time) / (b.time - a.time), 0.0, 1.0));
    glm::vec3 position = catmullRom(before.position, a.position, b.position, after.position, t);
    const glm::vec3 target = catmullRom(before.lookAt, a.lookAt, b.lookAt, after.lookAt, t);
    position.y = std::max(position.y,
                          groundBelow(terrain, position) + static_cast<float>(kCameraClearance_m));
    return lookingAt(position, target);
  };
}

CameraPath loadCameraPath(const std::filesystem::path& file, const Terrain& terrain) {
  TomlDocument document = TomlDocument::load(file);
  TomlTable root = document.root();
  std::vector<CameraKey> keys;
  std::vector<TomlTable> tables = root.tables("key");
  if (tables.size() < 2) root.fail("key", "a camera path needs at least two [[key]] tables");
  for (TomlTable& table : tables) {
    CameraKey key;
    key.time = table.number("time");
    if (!keys.empty() && key.time <= keys.back().time)
      table.fail("time", "key times must increase");
    const std::vector<double> p = table.numbers("position", 3);
    const std::vector<double> l = table.numbers("look_at", 3);
    key.position = worldFromMap(p[0], p[1], p[2]);
    key.lookAt = worldFromMap(l[0], l[1], l[2]);
    if (glm::length(key.lookAt - key.position) < 1e-3f)
      table.fail("look_at", "the camera cannot look at its own position");
    table.finish();
    keys.push_back(key);
  }
  root.finish();
  return keyframePath(std::move(keys), terrain);
}

}  // namespace eco
