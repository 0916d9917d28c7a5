#include "sim/plan/region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include <glm/common.hpp>

#include "sim/image_io.hpp"

namespace eco {
namespace {

double distanceToSegment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double length2 = ab.x * ab.x + ab.y * ab.y;
  const double t = length2 > 0.0
                       ? std::clamp(((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / length2, 0.0, 1.0)
                       : 0.0;
  const glm::dvec2 d = p - (a + t * ab);
  return std::hypot(d.x, d.y);
}

// Even-odd rule: a ray to the east crosses the outline an odd number of times.
bool insidePolygon(glm::dvec2 p, const std::vector<glm::dvec2>& corners) {
  bool inside = false;
  for (std::size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++) {
    const glm::dvec2 a = corners[i], b = corners[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
      inside = !inside;
  }
  return inside;
}

// Each cell whose centre lies within `buffer_m` of a masked cell's centre.
std::vector<std::uint8_t> widened(const std::vector<std::uint8_t>& mask, const Grid& g,
                                  double buffer_m) {
  if (buffer_m <= 0.0) return mask;
  std::vector<std::uint8_t> out(mask.size(), 0);
  const int rx = static_cast<int>(std::floor(buffer_m / g.dx_m));
  const int ry = static_cast<int>(std::floor(buffer_m / g.dy_m));
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      if (!mask[g.index(x, y)]) continue;
      for (int v = std::max(0, y - ry); v <= std::min(g.height - 1, y + ry); ++v)
        for (int u = std::max(0, x - rx); u <= std::min(g.width - 1, x + rx); ++u)
          if (std::hypot((u - x) * g.dx_m, (v - y) * g.dy_m) <= buffer_m) out[g.index(u, v)] = 1;
    }
  return out;
}

}  // namespace

MapBounds MapBounds::of(const Grid& g) {
  return {{-0.5 * g.dx_m, -0.5 * g.dy_m}, {(g.width - 0.5) * g.dx_m, (g.height - 0.5) * g.dy_m}};
}

Region::Region(const RegionSpec& spec, const Grid& grid, bool mayLieOutside)
    : spec_(spec), grid_(grid), bounds_(MapBounds::of(grid)), map_(MapBounds::of(grid)) {
  using Kind = RegionSpec::Kind;
  if (spec_.kind == Kind::Mask) {
    if (!std::filesystem::is_regular_file(spec_.mask))
      throw InputError(spec_.where, "mask file not found: " + spec_.mask.string());
    const SingleChannelImage image = readSingleChannel(spec_.mask);
    if (image.width != grid.width || image.height != grid.height)
      throw InputError(
          spec_.where,
          fmt::format("the mask {} is {} x {} pixels; the terrain is {} x {} cells",
                      spec_.mask.string(), image.width, image.height, grid.width, grid.height));
    // White is inside: at least half the stored type's maximum (128 of 255, 0.5 of 1).
    std::vector<std::uint8_t> mask(image.values.size(), 0);
    for (std::size_t c = 0; c < mask.size(); ++c) mask[c] = image.values[c] >= 0.5 * image.typeMax;
    mask_ = widened(mask, grid, spec_.buffer_m);
  }
  if (spec_.kind == Kind::Polygon || spec_.kind == Kind::Line) {
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const glm::dvec2& p : spec_.points) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    lo -= glm::dvec2(spec_.buffer_m);
    hi += glm::dvec2(spec_.buffer_m);
    bounds_ = {glm::max(lo, map_.min), glm::min(hi, map_.max)};
    const bool missesTheMap = !(bounds_.min.x < bounds_.max.x && bounds_.min.y < bounds_.max.y);
    if (missesTheMap && !mayLieOutside)
      throw InputError(
          spec_.where,
          fmt::format("the {} lies outside the map, which spans east {:.1f} .. {:.1f} m and "
                      "north {:.1f} .. {:.1f} m (map metres, as the trees CSV's x_m and y_m)",
                      spec_.kind == Kind::Polygon ? "polygon" : "line", map_.min.x, map_.max.x,
                      map_.min.y, map_.max.y));
    if (mayLieOutside) bounds_ = {lo, hi};
  }
  if (spec_.kind == Kind::Border)
    bounds_ = {map_.min - glm::dvec2(spec_.border_m), map_.max + glm::dvec2(spec_.border_m)};
}

double Region::distanceToOutline(glm::dvec2 p) const {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = spec_.points.size();
  const bool closed = spec_.kind == RegionSpec::Kind::Polygon;
  for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i)
    best = std::min(best, distanceToSegment(p, spec_.points[i], spec_.points[(i + 1) % n]));
  return best;
}

bool Region::insideShape(glm::dvec2 p) const {
  using Kind = RegionSpec::Kind;
  switch (spec_.kind) {
    case Kind::WholeMap:
      return map_.contains(p);
    case Kind::Polygon:
      return insidePolygon(p, spec_.points) ||
             (spec_.buffer_m > 0.0 && distanceToOutline(p) <= spec_.buffer_m);
    case Kind::Line:
      return distanceToOutline(p) <= spec_.buffer_m;
    case Kind::Mask: {
      const long cell = grid_.cellAt(p.x, p.y);
      return cell >= 0 && mask_[static_cast<std::size_t>(cell)];
    }
    case Kind::Border: {
      if (map_.contains(p)) return false;
      const double dx = std::max({map_.min.x - p.x, 0.0, p.x - map_.max.x});
      const double dy = std::max({map_.min.y - p.y, 0.0, p.y - map_.max.y});
      return std::hypot(dx, dy) <= spec_.border_m;
    }
  }
  return false;
}

bool Region::contains(glm::dvec2 p) const {
  if (p.x < bounds_.min.x || p.y < bounds_.min.y || p.x > bounds_.max.x || p.y > bounds_.max.y)
    return false;
  return insideShape(p);
}

double Region::areaOnLandscape_m2(const Terrain& terrain) const {
  const Grid& g = terrain.grid;
  std::size_t cells = 0;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      if (!terrain.isOutside(g.index(x, y)) && contains({g.eastOf(x), g.northOf(y)})) ++cells;
  return static_cast<double>(cells) * g.dx_m * g.dy_m;
}

}  // namespace eco
