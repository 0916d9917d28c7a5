// Fixed16<kMost>: a number from 0 to kMost kept in 16 bits, for the columns of numbers kept
// by the hundred million (a landscape's plants) that need no float's precision.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace eco {

// Rounded to the nearest of 65,536 steps, so to within half a step, kMost / 131,070; the
// ends are kept exactly. A value beyond the range is kept as its nearest end, and not a
// number as 0: the caller keeps values in range (the range is chosen to hold every value
// the program makes), so a column holds no number a checkpoint could not hold.
template <int kMost>
class Fixed16 {
 public:
  static_assert(kMost > 0);
  static constexpr double kStepsPerUnit = 65535.0 / kMost;
  static constexpr double kStep = 1.0 / kStepsPerUnit;

  Fixed16() = default;
  Fixed16(double value)  // NOLINT(google-explicit-constructor): assigned like the float it was
      : raw_(nearestStep((value > 0.0 ? std::min(value, double{kMost}) : 0.0) * kStepsPerUnit)) {}
  // Compared, too, as the float (each of the 65,536 steps is a float of its own).
  operator float() const {  // NOLINT(google-explicit-constructor)
    return static_cast<float>(raw_ / kStepsPerUnit);
  }

 private:
  // std::lround of steps from 0 to 65,535 (halves away from zero), inline: the floor and the
  // difference from it are exact. Several columns of every plant, every year, and lround is
  // a call into the C library.
  static std::uint16_t nearestStep(double steps) {
    const double whole = std::floor(steps);
    return static_cast<std::uint16_t>(whole + (steps - whole >= 0.5 ? 1.0 : 0.0));
  }

  std::uint16_t raw_ = 0;
};

}  // namespace eco
