#include "sim/plan/layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "core/random.hpp"

namespace eco {
namespace {

// Contour rows need a slope to follow: below 1 % the contour lines wander with every
// centimetre of relief.
constexpr double kFlattestContourGradient = 0.01;
constexpr int kDartsPerTree = 30;

bool onLandscape(const Terrain& terrain, glm::dvec2 p) {
  const long cell = terrain.grid.cellAt(p.x, p.y);
  return cell >= 0 && !terrain.isOutside(static_cast<std::size_t>(cell));
}

// Calls f(x, y) for the cells whose centres lie within the region's bounds.
template <typename F>
void forCellsInBounds(const Grid& g, const MapBounds& b, F&& f) {
  const int x0 = std::max(0, static_cast<int>(std::floor(b.min.x / g.dx_m)));
  const int x1 = std::min(g.width - 1, static_cast<int>(std::ceil(b.max.x / g.dx_m)));
  const int y0 = std::max(0, static_cast<int>(std::floor((g.height - 1) - b.max.y / g.dy_m)));
  const int y1 =
      std::min(g.height - 1, static_cast<int>(std::ceil((g.height - 1) - b.min.y / g.dy_m)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) f(x, y);
}

// A regular grid of rows `rowSpacing` apart running east-west, trees `spacing` apart along
// them, every other row shifted by `rowShift` of the spacing.
std::vector<PlantingSpot> gridSpots(const Planting& planting, const Region& region,
                                    const Terrain& terrain, double rowShift) {
  const MapBounds map = MapBounds::of(terrain.grid), b = region.bounds();
  const double s = planting.spacing_m, r = planting.rowSpacing_m;
  std::vector<PlantingSpot> spots;
  const int row0 = std::max(0, static_cast<int>(std::floor((b.min.y - map.min.y) / r - 0.5)));
  for (int row = row0;; ++row) {
    const double north = map.min.y + (row + 0.5) * r;
    if (north > b.max.y || north >= map.max.y) break;
    const double shift = (row % 2) * rowShift * s;
    const int col0 =
        std::max(0, static_cast<int>(std::floor((b.min.x - map.min.x - shift) / s - 0.5)));
    for (int col = col0;; ++col) {
      const glm::dvec2 p(map.min.x + (col + 0.5) * s + shift, north);
      if (p.x > b.max.x || p.x >= map.max.x) break;
      if (region.contains(p) && onLandscape(terrain, p)) spots.push_back({p, row});
    }
  }
  return spots;
}

// Contour lines by marching squares over the cell centres, chained into polylines, with
// trees every `spacing` along each.
std::vector<PlantingSpot> contourSpots(const Planting& planting, const Region& region,
                                       const Terrain& terrain, double levelStep_m) {
  const Grid& g = terrain.grid;
  struct Segment {
    int level;
    std::uint64_t key[2];  // (level, grid edge) of each end
    glm::dvec2 end[2];
  };
  std::vector<Segment> segments;
  const std::uint64_t edges = 2 * static_cast<std::uint64_t>(g.cellCount());
  auto keyOf = [&](int level, std::uint64_t edge) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(level) + (1 << 30)) * edges + edge;
  };
  forCellsInBounds(g, region.bounds(), [&](int x, int y) {
    if (x + 1 >= g.width || y + 1 >= g.height) return;
    // Corners clockwise from the north-west, edges top, right, bottom, left between them.
    const std::array<std::pair<int, int>, 4> corner{
        {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}};
    std::array<double, 4> h;
    for (int c = 0; c < 4; ++c) {
      const std::size_t cell = g.index(corner[c].first, corner[c].second);
      if (terrain.isOutside(cell)) return;
      h[c] = terrain.height_m[cell];
    }
    const std::array<std::uint64_t, 4> edge{2 * static_cast<std::uint64_t>(g.index(x, y)),
                                            2 * static_cast<std::uint64_t>(g.index(x + 1, y)) + 1,
                                            2 * static_cast<std::uint64_t>(g.index(x, y + 1)),
                                            2 * static_cast<std::uint64_t>(g.index(x, y)) + 1};
    const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
    // Levels sit at (k + 1/2) steps, so a flat cell never lies on one.
    for (int k = static_cast<int>(std::ceil(*lo / levelStep_m - 0.5));
         k <= static_cast<int>(std::floor(*hi / levelStep_m - 0.5)); ++k) {
      const double level = (k + 0.5) * levelStep_m;
      std::array<bool, 4> above;
      for (int c = 0; c < 4; ++c) above[c] = h[c] > level;
      auto crossing = [&](int e) {
        const int a = e, b = (e + 1) % 4;
        const double t = (level - h[a]) / (h[b] - h[a]);
        const glm::dvec2 pa(g.eastOf(corner[a].first), g.northOf(corner[a].second));
        const glm::dvec2 pb(g.eastOf(corner[b].first), g.northOf(corner[b].second));
        return pa + t * (pb - pa);
      };
      std::array<int, 4> crossed;
      int n = 0;
      for (int e = 0; e < 4; ++e)
        if (above[e] != above[(e + 1) % 4]) crossed[n++] = e;
      auto add = [&](int e0, int e1) {
        segments.push_back(
            {k, {keyOf(k, edge[e0]), keyOf(k, edge[e1])}, {crossing(e0), crossing(e1)}});
      };
      if (n == 2) {
        add(crossed[0], crossed[1]);
      } else if (n == 4) {
        // A saddle: the centre's side decides which corners the lines cut off.
        const bool centreAbove = (h[0] + h[1] + h[2] + h[3]) / 4.0 > level;
        if (centreAbove == above[0]) {
          add(0, 1), add(2, 3);
        } else {
          add(3, 0), add(1, 2);
        }
      }
    }
  });
  std::unordered_map<std::uint64_t, std::array<int, 2>> atKey;
  for (int s = 0; s < static_cast<int>(segments.size()); ++s)
    for (std::uint64_t key : segments[s].key) {
      auto [it, fresh] = atKey.try_emplace(key, std::array<int, 2>{-1, -1});
      it->second[it->second[0] < 0 ? 0 : 1] = s;
    }
  auto degree = [&](std::uint64_t key) { return atKey[key][1] < 0 ? 1 : 2; };
  std::vector<char> visited(segments.size(), 0);
  std::vector<PlantingSpot> spots;
  // Trees one spacing apart along an open line, from half a spacing in; around a closed
  // one the spacing is stretched a little so that the last gap is no shorter than the rest.
  auto plantAlong = [&](const std::vector<glm::dvec2>& line, bool closed, int row) {
    double length = 0.0;
    for (std::size_t k = 1; k < line.size(); ++k)
      length += std::hypot(line[k].x - line[k - 1].x, line[k].y - line[k - 1].y);
    double step = planting.spacing_m, at = 0.5 * step;
    if (closed) {
      step = length / std::max(1.0, std::floor(length / planting.spacing_m));
      at = 0.0;
    }
    double start = 0.0;  // along the line, where the current piece begins
    for (std::size_t k = 1; k < line.size(); ++k) {
      const glm::dvec2 a = line[k - 1], b = line[k];
      const double piece = std::hypot(b.x - a.x, b.y - a.y);
      // Around a closed line the last tree stands a whole step before the first.
      for (; at < start + piece && !(closed && at > length - 0.5 * step); at += step) {
        const glm::dvec2 p = a + ((at - start) / piece) * (b - a);
        if (region.contains(p) && onLandscape(terrain, p)) spots.push_back({p, row});
      }
      start += piece;
    }
  };
  // Follows segments end to end from `s`, leaving it by its end `startEnd`'s other end.
  auto walk = [&](int s, int startEnd) {
    const int row = segments[s].level;
    std::vector<glm::dvec2> line{segments[s].end[startEnd]};
    const std::uint64_t first = segments[s].key[startEnd];
    int end = startEnd;
    bool closed = false;
    for (;;) {
      visited[s] = 1;
      line.push_back(segments[s].end[1 - end]);
      const std::uint64_t key = segments[s].key[1 - end];
      const std::array<int, 2>& both = atKey[key];
      const int next = both[0] == s ? both[1] : both[0];
      if (next < 0 || visited[next]) {
        closed = key == first;
        break;
      }
      end = segments[next].key[0] == key ? 0 : 1;
      s = next;
    }
    plantAlong(line, closed, row);
  };
  // Open lines from one of their ends, then the closed ones.
  for (int s = 0; s < static_cast<int>(segments.size()); ++s)
    for (int e = 0; e < 2 && !visited[s]; ++e)
      if (degree(segments[s].key[e]) == 1) walk(s, e);
  for (int s = 0; s < static_cast<int>(segments.size()); ++s)
    if (!visited[s]) walk(s, 0);
  return spots;
}

std::vector<PlantingSpot> randomSpots(const Planting& planting, const Region& region,
                                      const Terrain& terrain, std::uint64_t seed) {
  const double area = region.areaOnLandscape_m2(terrain);
  const auto target =
      static_cast<std::size_t>(std::llround(area / (planting.spacing_m * planting.spacing_m)));
  const MapBounds b = region.bounds();  // a planting's region lies within the map
  const double d = planting.minDistance_m;
  // A hash grid of cells of side d: a tree closer than d lies in one of the 3 x 3 around.
  const double cell = d > 0.0 ? d : 1.0;
  const int nx = static_cast<int>(std::ceil((b.max.x - b.min.x) / cell)) + 1;
  const int ny = static_cast<int>(std::ceil((b.max.y - b.min.y) / cell)) + 1;
  std::unordered_map<std::int64_t, std::vector<glm::dvec2>> near;
  auto bucket = [&](int x, int y) { return static_cast<std::int64_t>(y) * nx + x; };
  std::vector<PlantingSpot> spots;
  Rng rng(seed);
  for (std::size_t dart = 0; dart < target * kDartsPerTree && spots.size() < target; ++dart) {
    const glm::dvec2 p(b.min.x + rng.uniform() * (b.max.x - b.min.x),
                       b.min.y + rng.uniform() * (b.max.y - b.min.y));
    if (!region.contains(p) || !onLandscape(terrain, p)) continue;
    const int bx = static_cast<int>((p.x - b.min.x) / cell),
              by = static_cast<int>((p.y - b.min.y) / cell);
    bool free = true;
    for (int y = std::max(0, by - 1); free && y <= std::min(ny - 1, by + 1); ++y)
      for (int x = std::max(0, bx - 1); free && x <= std::min(nx - 1, bx + 1); ++x) {
        const auto found = near.find(bucket(x, y));
        if (found == near.end()) continue;
        for (const glm::dvec2& q : found->second)
          if (std::hypot(q.x - p.x, q.y - p.y) < d) free = false;
      }
    if (!free) continue;
    near[bucket(bx, by)].push_back(p);
    spots.push_back({p, 0});
  }
  return spots;
}

}  // namespace

double meanGradient(const Terrain& terrain, const Region& region) {
  const Grid& g = terrain.grid;
  double sum = 0.0;
  std::size_t cells = 0;
  forCellsInBounds(g, region.bounds(), [&](int x, int y) {
    if (x == 0 || y == 0 || x + 1 >= g.width || y + 1 >= g.height) return;
    for (std::size_t c : {g.index(x, y), g.index(x - 1, y), g.index(x + 1, y), g.index(x, y - 1),
                          g.index(x, y + 1)})
      if (terrain.isOutside(c)) return;
    if (!region.contains({g.eastOf(x), g.northOf(y)})) return;
    const double gx = (terrain.heightAt(x + 1, y) - terrain.heightAt(x - 1, y)) / (2.0 * g.dx_m);
    const double gy = (terrain.heightAt(x, y - 1) - terrain.heightAt(x, y + 1)) / (2.0 * g.dy_m);
    sum += std::hypot(gx, gy);
    ++cells;
  });
  return cells ? sum / static_cast<double>(cells) : 0.0;
}

PlantingLayoutResult layoutPlanting(const Planting& planting, const Region& region,
                                    const Terrain& terrain, std::uint64_t seed) {
  switch (planting.layout) {
    case PlantingLayout::Square:
      return {gridSpots(planting, region, terrain, 0.0), {}};
    case PlantingLayout::Triangular:
      return {gridSpots(planting, region, terrain, 0.5), {}};
    case PlantingLayout::Random:
      return {randomSpots(planting, region, terrain, seed), {}};
    case PlantingLayout::Contour: {
      const double gradient = meanGradient(terrain, region);
      if (gradient < kFlattestContourGradient)
        return {gridSpots(planting, region, terrain, 0.0),
                "its ground is flatter than 1 %, so its contour rows are straight east-west rows"};
      return {contourSpots(planting, region, terrain, planting.rowSpacing_m * gradient), {}};
    }
  }
  return {};
}

}  // namespace eco
