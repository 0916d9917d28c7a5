// The camera, in the world frame (core/frames.hpp: x east, y up, z south, metres).
#pragma once

#include <optional>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/frames.hpp"
#include "sim/terrain.hpp"

namespace eco {

// The ground's altitude under a world point (Terrain::altitudeAt of its map position).
float groundBelow(const Terrain& terrain, glm::vec3 world);

struct Camera {
  glm::vec3 position{0.0f};
  float yaw_deg = 0.0f;    // compass bearing of the view direction: 0 north, 90 east
  float pitch_deg = 0.0f;  // up from the horizon
  float fovY_deg = 50.0f;
  float near_m = 0.5f;
  float far_m = 30000.0f;

  glm::vec3 forward() const;
  glm::vec3 right() const;  // horizontal, to the right of the view direction
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;  // reversed nothing: depth 0 near, 1 far
  // Pixels per metre at distance 1 for a viewport this many pixels high.
  float pixelsPerRadian(int viewportHeight) const;
};

// "X,Y,Z,YAW,PITCH": map east, map north, altitude (metres) and the two angles (degrees).
// nullopt when the text is not five numbers.
std::optional<Camera> parseCamera(const std::string& text);

enum class CameraPreset { Overview, Ground, Low };
// Overview: from the south, high enough to see the whole map, looking down at its centre.
// Ground: eye height 1.7 m at the map centre, looking north.
// Low: 60 m above the ground a sixth of the way up the map from its south edge, looking
// north 12 degrees down: near trees to the horizon (the benchmark's view).
Camera presetCamera(CameraPreset preset, const Terrain& terrain);

}  // namespace eco
