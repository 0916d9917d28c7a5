#include "sim/ecology/growth.hpp"

#include <algorithm>
#include <cmath>

namespace eco {

double grownValue(const GrowthCurve& curve, double value, double vigor) {
  const double age = curve.ageOf(value);
  if (!std::isfinite(age)) return std::min(value, curve.max);
  const double increment = curve.at(age + 1.0) - curve.at(age);
  return std::min(curve.max, value + std::clamp(vigor, 0.0, 1.0) * increment);
}

double crownRadiusOf(const LifeHistory& life, double dbh_m, double height_m) {
  return std::min(life.crownRadius_m(dbh_m), 0.5 * height_m);
}

double seedCount(const LifeHistory& life, double dbh_m, double vigor) {
  const double reference_m = std::min(0.3, life.dbh_m.max);
  const double size = dbh_m / reference_m;
  return life.seedsPerYear * size * size * std::clamp(vigor, 0.0, 1.0);
}

double mortalityProbability(const LifeHistory& life, int age_years, int stressYears) {
  if (age_years >= life.maxAge_years) return 1.0;
  double p = 4.605 / life.maxAge_years;
  if (stressYears >= life.stressYearsTolerated) p = std::max(p, 0.368);
  return std::min(p, 1.0);
}

}  // namespace eco
