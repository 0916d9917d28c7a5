// What every tree generator is asked to build: which individual, at what age, at what
// moment of the wind, with which wind overrides.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

namespace eco {

struct TreeBuildOptions {
  std::uint64_t seed = 1;  // the individual: phases and small variations
  double age = 1.0;        // 0 = seedling, 1 = mature (growth rule in docs/model.md)
  double windTime = 0.0;   // t in alpha_x(t), alpha_z(t), radians of the sway oscillation
  // Wind overrides; unset means the species file's values.
  std::optional<double> windDirected;       // w_g
  std::optional<double> windUndirected;     // w_s
  std::optional<glm::dvec3> windDirection;  // w, toward which the wind blows (tree frame)
  bool leaves = true;
};

}  // namespace eco
