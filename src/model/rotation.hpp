// Rotation matrices about the branch frame's axes and about an arbitrary axis, in degrees,
// for column vectors (v' = R v).
#pragma once

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace eco {

inline double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

inline glm::mat3 rotationX(double degrees) {
  float c = static_cast<float>(std::cos(radians(degrees)));
  float s = static_cast<float>(std::sin(radians(degrees)));
  return glm::mat3(1, 0, 0, 0, c, s, 0, -s, c);  // glm is column-major: columns listed
}

inline glm::mat3 rotationY(double degrees) {
  float c = static_cast<float>(std::cos(radians(degrees)));
  float s = static_cast<float>(std::sin(radians(degrees)));
  return glm::mat3(c, 0, -s, 0, 1, 0, s, 0, c);
}

inline glm::mat3 rotationZ(double degrees) {
  float c = static_cast<float>(std::cos(radians(degrees)));
  float s = static_cast<float>(std::sin(radians(degrees)));
  return glm::mat3(c, s, 0, -s, c, 0, 0, 0, 1);
}

// Rodrigues' formula; `axis` must be a unit vector.
inline glm::mat3 rotationAbout(glm::vec3 axis, double degrees) {
  float c = static_cast<float>(std::cos(radians(degrees)));
  float s = static_cast<float>(std::sin(radians(degrees)));
  float t = 1.0f - c;
  float x = axis.x, y = axis.y, z = axis.z;
  // One column of the matrix per line.
  // clang-format off
  return glm::mat3(t * x * x + c,     t * x * y + s * z, t * x * z - s * y,
                   t * x * y - s * z, t * y * y + c,     t * y * z + s * x,
                   t * x * z + s * y, t * y * z - s * x, t * z * z + c);
  // clang-format on
}

// Rotation about y x target, which turns the branch axis y toward the target direction
// (given in the branch frame) by `degrees`.
inline glm::mat3 tiltToward(glm::vec3 targetLocal, double degrees) {
  glm::vec3 axis = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), targetLocal);
  float len = glm::length(axis);
  if (len < 1e-6f || degrees == 0.0) return glm::mat3(1.0f);
  return rotationAbout(axis / len, degrees);
}

}  // namespace eco
