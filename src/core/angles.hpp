// Degrees and radians, spelled once. User files, species and scenarios give angles in
// degrees (suffix _deg); the maths takes radians. Both conversions multiply by one
// constant, the same as glm::radians and glm::degrees, so results agree bit for bit
// wherever either is used.
#pragma once

#include <numbers>

namespace eco {

inline constexpr double kPi = std::numbers::pi;

constexpr double radians(double degrees) {
  return degrees * (kPi / 180.0);
}
constexpr float radians(float degrees) {
  return degrees * static_cast<float>(kPi / 180.0);
}
constexpr double degrees(double radians) {
  return radians * (180.0 / kPi);
}
constexpr float degrees(float radians) {
  return radians * static_cast<float>(180.0 / kPi);
}

}  // namespace eco
