#include "core/polyline.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace eco {

Polyline::Polyline(std::vector<ControlPoint> points) : points_(std::move(points)) {
  ECO_ASSERT(!points_.empty(), "a polyline needs at least one control point");
  for (std::size_t i = 1; i < points_.size(); ++i)
    ECO_ASSERT(points_[i].x >= points_[i - 1].x, "abscissae must not decrease: x["
                                                     << i - 1 << "]=" << points_[i - 1].x << " x["
                                                     << i << "]=" << points_[i].x);
}

double Polyline::operator()(double x) const {
  // First point strictly right of x; the segment [after-1, after] then has positive width.
  auto after = std::upper_bound(points_.begin(), points_.end(), x,
                                [](double value, const ControlPoint& p) { return value < p.x; });
  if (after == points_.begin()) return points_.front().y;
  if (after == points_.end()) return points_.back().y;
  const ControlPoint& a = *(after - 1);
  const ControlPoint& b = *after;
  double t = (x - a.x) / (b.x - a.x);
  return a.y + t * (b.y - a.y);
}

}  // namespace eco
