// Piecewise-linear graphs y(x), as EcoMod's local parameters (Zamuda et al., section II.B):
// control points at any real abscissa, linear between them, constant outside the first and
// last point. Two points may share an abscissa to make a vertical step; at the step itself
// the value after the step is taken (the graph is right-continuous).
#pragma once

#include <span>
#include <vector>

namespace eco {

struct ControlPoint {
  double x = 0.0;
  double y = 0.0;
};

class Polyline {
 public:
  Polyline() : points_{{0.0, 0.0}} {}
  // Requires at least one point and non-decreasing abscissae (checked; readers of user
  // files validate first so the user gets a file:line error instead).
  explicit Polyline(std::vector<ControlPoint> points);
  static Polyline constant(double y) { return Polyline({{0.0, y}}); }

  double operator()(double x) const;
  std::span<const ControlPoint> points() const { return points_; }

 private:
  std::vector<ControlPoint> points_;
};

}  // namespace eco
