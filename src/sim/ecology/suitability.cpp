#include "sim/ecology/suitability.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace eco {

std::array<double, kConditionCount> conditionSuitabilities(const ToleranceCurves& tolerance,
                                                           const ConditionFields& fields,
                                                           std::size_t cell) {
  const Field* field[kConditionCount] = {&fields.altitude_m, &fields.slope_deg, &fields.moisture,
                                         &fields.windiness};
  std::array<double, kConditionCount> values;
  for (int i = 0; i < kConditionCount; ++i)
    values[i] = std::clamp(tolerance.of(static_cast<Condition>(i))((*field[i])[cell]), 0.0, 1.0);
  return values;
}

double combineSuitabilities(const std::array<double, kConditionCount>& values,
                            SuitabilityRule rule) {
  double result = 1.0;
  for (double v : values)
    result = rule == SuitabilityRule::Minimum ? std::min(result, v) : result * v;
  return result;
}

Field siteSuitability(const ToleranceCurves& tolerance, const ConditionFields& fields,
                      SuitabilityRule rule) {
  Field result(fields.grid.cellCount());
  tbb::parallel_for(std::size_t{0}, result.size(), [&](std::size_t cell) {
    const double suitability =
        combineSuitabilities(conditionSuitabilities(tolerance, fields, cell), rule);
    // NaN conditions: a cell outside the landscape, where nothing grows.
    result[cell] = std::isfinite(suitability) ? static_cast<float>(suitability) : 0.0f;
  });
  return result;
}

}  // namespace eco
