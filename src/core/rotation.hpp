// Rotations for column vectors (v' = R v): matrices about a frame's axes and about an
// arbitrary axis, angles in degrees (the tree model's frames), and the same rotation of a
// single double-precision vector, angle in radians (the L-system turtle's state).
#pragma once

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/angles.hpp"

namespace eco {

inline glm::mat3 rotationX(double angle_deg) {
  float c = static_cast<float>(std::cos(radians(angle_deg)));
  float s = static_cast<float>(std::sin(radians(angle_deg)));
  return glm::mat3(1, 0, 0, 0, c, s, 0, -s, c);  // glm is column-major: columns listed
}

inline glm::mat3 rotationY(double angle_deg) {
  float c = static_cast<float>(std::cos(radians(angle_deg)));
  float s = static_cast<float>(std::sin(radians(angle_deg)));
  return glm::mat3(c, 0, -s, 0, 1, 0, s, 0, c);
}

inline glm::mat3 rotationZ(double angle_deg) {
  float c = static_cast<float>(std::cos(radians(angle_deg)));
  float s = static_cast<float>(std::sin(radians(angle_deg)));
  return glm::mat3(c, s, 0, -s, c, 0, 0, 0, 1);
}

// Rodrigues' formula; `axis` must be a unit vector.
inline glm::mat3 rotationAbout(glm::vec3 axis, double angle_deg) {
  float c = static_cast<float>(std::cos(radians(angle_deg)));
  float s = static_cast<float>(std::sin(radians(angle_deg)));
  float t = 1.0f - c;
  float x = axis.x, y = axis.y, z = axis.z;
  // One column of the matrix per line.
  // clang-format off
  return glm::mat3(t * x * x + c,     t * x * y + s * z, t * x * z - s * y,
                   t * x * y - s * z, t * y * y + c,     t * y * z + s * x,
                   t * x * z + s * y, t * y * z - s * x, t * z * z + c);
  // clang-format on
}

// Rodrigues' formula for one vector: v turned about the unit axis k by `angle` radians.
inline glm::dvec3 rotateAbout(const glm::dvec3& v, const glm::dvec3& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
}

// Rotation about y x target, which turns the branch axis y toward the target direction
// (given in the branch frame) by `angle_deg`.
inline glm::mat3 tiltToward(glm::vec3 targetLocal, double angle_deg) {
  glm::vec3 axis = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), targetLocal);
  float len = glm::length(axis);
  if (len < 1e-6f || angle_deg == 0.0) return glm::mat3(1.0f);
  return rotationAbout(axis / len, angle_deg);
}

}  // namespace eco
