#include "sim/ecology/dispersal.hpp"

#include <cmath>
#include <numbers>

namespace eco {

glm::dvec2 seedOffset(const LifeHistory& life, glm::dvec2 downwind, Rng& rng) {
  const bool far = life.longDistanceFraction > 0.0 && rng.uniform() < life.longDistanceFraction;
  const double mean_m = far ? life.longDistanceMean_m : life.dispersalMean_m;
  const double distance = -mean_m * std::log(1.0 - rng.uniform());
  const double angle = 2.0 * std::numbers::pi * rng.uniform();
  glm::dvec2 offset(distance * std::cos(angle), distance * std::sin(angle));
  if (life.dispersal == DispersalVector::Wind) offset += life.downwindBias * distance * downwind;
  return offset;
}

}  // namespace eco
