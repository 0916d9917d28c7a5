// A closed interval of allowed values: a key's bounds in a user file, a slider's ends.
#pragma once

#include <algorithm>
#include <limits>

namespace eco {

struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();

  bool contains(double value) const { return value >= min && value <= max; }
  double clamp(double value) const { return std::clamp(value, min, max); }
};

}  // namespace eco
