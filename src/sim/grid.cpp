#include "sim/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eco {

FieldStats statsOf(const Field& field) {
  FieldStats s{std::numeric_limits<double>::max(), 0.0, std::numeric_limits<double>::lowest()};
  double sum = 0.0;
  std::size_t count = 0;
  for (float v : field) {
    if (!std::isfinite(v)) continue;
    s.min = std::min(s.min, static_cast<double>(v));
    s.max = std::max(s.max, static_cast<double>(v));
    sum += v;
    ++count;
  }
  if (count == 0) return {};
  s.mean = sum / static_cast<double>(count);
  return s;
}

}  // namespace eco
