#include "sim/grid.hpp"

#include <algorithm>

namespace eco {

FieldStats statsOf(const Field& field) {
  if (field.empty()) return {};
  FieldStats s{field.front(), 0.0, field.front()};
  double sum = 0.0;
  for (float v : field) {
    s.min = std::min(s.min, static_cast<double>(v));
    s.max = std::max(s.max, static_cast<double>(v));
    sum += v;
  }
  s.mean = sum / static_cast<double>(field.size());
  return s;
}

}  // namespace eco
