#include "core/random.hpp"

#include <cmath>
#include <numbers>

namespace eco {

double Rng::normal() {
  double u1 = uniform();
  double u2 = uniform();
  // 1 - u1 is in (0, 1], so the logarithm is finite.
  return std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

int Rng::stochasticRound(double x) {
  double whole = std::floor(x);
  return static_cast<int>(whole) + (uniform() < x - whole ? 1 : 0);
}

}  // namespace eco
