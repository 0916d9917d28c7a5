// What every tree generator is asked to build: which individual, at what age, at what
// moment of the wind, with which wind overrides, shaped by which site.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/vec2.hpp>
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
  // Shaping by the site (tree_shaping.hpp): a horizontal directed vector (east, south, w_g
  // units) added to the species' own, and the share of the stem below the crown base whose
  // side branches are pruned. Zero for the species' own tree.
  glm::dvec2 lean{0.0};
  double clearBole = 0.0;
};

}  // namespace eco
