#include "sim/terrain_mesh.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace eco {
namespace {

// Height at (x, y), continued linearly past the edges (2 z_edge - z_inside).
double extendedHeight(const Terrain& terrain, int x, int y) {
  const Grid& g = terrain.grid;
  if (x < 0) return 2.0 * extendedHeight(terrain, 0, y) - extendedHeight(terrain, -x, y);
  if (x >= g.width)
    return 2.0 * extendedHeight(terrain, g.width - 1, y) -
           extendedHeight(terrain, 2 * (g.width - 1) - x, y);
  if (y < 0) return 2.0 * extendedHeight(terrain, x, 0) - extendedHeight(terrain, x, -y);
  if (y >= g.height)
    return 2.0 * extendedHeight(terrain, x, g.height - 1) -
           extendedHeight(terrain, x, 2 * (g.height - 1) - y);
  return terrain.heightAt(x, y);
}

}  // namespace

Gradient terrainGradient(const Terrain& terrain, int x, int y) {
  const Grid& g = terrain.grid;
  auto z = [&](int dx, int dy) { return extendedHeight(terrain, x + dx, y + dy); };
  // Row -1 is the northern neighbour row (row 0 of the grid is the north edge).
  double east = ((z(1, -1) + 2.0 * z(1, 0) + z(1, 1)) - (z(-1, -1) + 2.0 * z(-1, 0) + z(-1, 1))) /
                (8.0 * g.dx_m);
  double north = ((z(-1, -1) + 2.0 * z(0, -1) + z(1, -1)) - (z(-1, 1) + 2.0 * z(0, 1) + z(1, 1))) /
                 (8.0 * g.dy_m);
  return {east, north};
}

std::array<std::uint32_t, 6> squareTriangles(const Grid& grid, int x, int y) {
  const auto nw = static_cast<std::uint32_t>(grid.index(x, y)), ne = nw + 1;
  const auto sw = static_cast<std::uint32_t>(grid.index(x, y + 1)), se = sw + 1;
  return {nw, sw, ne, ne, sw, se};
}

std::vector<std::uint32_t> terrainTriangles(const Grid& grid) {
  std::vector<std::uint32_t> indices;
  indices.reserve(static_cast<std::size_t>(std::max(grid.width - 1, 0)) *
                  std::max(grid.height - 1, 0) * 6);
  for (int y = 0; y + 1 < grid.height; ++y)
    for (int x = 0; x + 1 < grid.width; ++x) {
      const std::array<std::uint32_t, 6> square = squareTriangles(grid, x, y);
      indices.insert(indices.end(), square.begin(), square.end());
    }
  return indices;
}

glm::vec3 RimVertex::position(const Terrain& terrain) const {
  return cellPosition(terrain, x, y) + glm::vec3(east_m, north_m, 0.0f);
}

glm::vec2 RimVertex::mapUv(const Grid& g) const {
  return {static_cast<float>((x + 0.5 + east_m / g.dx_m) / g.width),
          static_cast<float>((y + 0.5 - north_m / g.dy_m) / g.height)};
}

TerrainRim terrainRim(const Grid& g) {
  TerrainRim rim;
  const auto cells = static_cast<std::uint32_t>(g.cellCount());
  const float halfX = static_cast<float>(0.5 * g.dx_m), halfY = static_cast<float>(0.5 * g.dy_m);
  auto add = [&](int x, int y, float east, float north) {
    rim.vertices.push_back({x, y, east, north});
    return cells + static_cast<std::uint32_t>(rim.vertices.size() - 1);
  };
  auto cell = [&](int x, int y) { return static_cast<std::uint32_t>(g.index(x, y)); };
  // Corners in counter-clockwise order seen from above: south-west, south-east,
  // north-east, north-west.
  auto quad = [&](std::uint32_t sw, std::uint32_t se, std::uint32_t ne, std::uint32_t nw) {
    rim.triangles.insert(rim.triangles.end(), {sw, se, ne, sw, ne, nw});
  };
  const int w = g.width, h = g.height;
  std::vector<std::uint32_t> north(w), south(w), west(h), east(h);
  for (int x = 0; x < w; ++x)
    north[x] = add(x, 0, 0.0f, halfY), south[x] = add(x, h - 1, 0.0f, -halfY);
  for (int y = 0; y < h; ++y)
    west[y] = add(0, y, -halfX, 0.0f), east[y] = add(w - 1, y, halfX, 0.0f);
  for (int x = 0; x + 1 < w; ++x) {
    quad(cell(x, 0), cell(x + 1, 0), north[x + 1], north[x]);
    quad(south[x], south[x + 1], cell(x + 1, h - 1), cell(x, h - 1));
  }
  for (int y = 0; y + 1 < h; ++y) {  // y + 1 is the row south of y
    quad(west[y + 1], cell(0, y + 1), cell(0, y), west[y]);
    quad(cell(w - 1, y + 1), east[y + 1], east[y], cell(w - 1, y));
  }
  quad(west[0], cell(0, 0), north[0], add(0, 0, -halfX, halfY));
  quad(cell(w - 1, 0), east[0], add(w - 1, 0, halfX, halfY), north[w - 1]);
  quad(add(0, h - 1, -halfX, -halfY), south[0], cell(0, h - 1), west[h - 1]);
  quad(south[w - 1], add(w - 1, h - 1, halfX, -halfY), east[h - 1], cell(w - 1, h - 1));
  return rim;
}

std::vector<DrawnVertex> drawnTerrainVertices(const Terrain& terrain, const TerrainRim& rim) {
  const Grid& g = terrain.grid;
  std::vector<DrawnVertex> vertices;
  vertices.reserve(g.cellCount() + rim.vertices.size());
  auto add = [&](const RimVertex& v) {
    vertices.push_back({v.position(terrain), terrainNormal(terrain, v.x, v.y), v.mapUv(g)});
  };
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) add({.x = x, .y = y});  // a cell is a rim vertex unmoved
  for (const RimVertex& v : rim.vertices) add(v);
  return vertices;
}

glm::vec3 cellPosition(const Terrain& terrain, int x, int y) {
  const Grid& g = terrain.grid;
  return {static_cast<float>(g.eastOf(x)), static_cast<float>(g.northOf(y)),
          terrain.heightAt(x, y)};
}

glm::dvec3 terrainNormal(const Terrain& terrain, int x, int y) {
  const Gradient g = terrainGradient(terrain, x, y);
  return glm::normalize(glm::dvec3(-g.east, -g.north, 1.0));
}

float altitudeOnTriangles(const Terrain& terrain, double east_m, double north_m) {
  const Grid& grid = terrain.grid;
  // The square (x0, y0)..(x1, y1) and the position inside it: tx toward the east, ty toward
  // the south (rows count from the north edge).
  const double fx = std::clamp(east_m / grid.dx_m, 0.0, grid.width - 1.0);
  const double fy = std::clamp((grid.height - 1) - north_m / grid.dy_m, 0.0, grid.height - 1.0);
  const int x0 = std::clamp(static_cast<int>(fx), 0, std::max(grid.width - 2, 0));
  const int y0 = std::clamp(static_cast<int>(fy), 0, std::max(grid.height - 2, 0));
  const int x1 = std::min(x0 + 1, grid.width - 1), y1 = std::min(y0 + 1, grid.height - 1);
  const double tx = fx - x0, ty = fy - y0;
  const double nw = terrain.heightAt(x0, y0), ne = terrain.heightAt(x1, y0),
               sw = terrain.heightAt(x0, y1), se = terrain.heightAt(x1, y1);
  // The triangle (NW, SW, NE) holds tx + ty <= 1, the triangle (NE, SW, SE) the rest.
  if (tx + ty <= 1.0) return static_cast<float>(nw + tx * (ne - nw) + ty * (sw - nw));
  return static_cast<float>(se + (1.0 - tx) * (sw - se) + (1.0 - ty) * (ne - se));
}

}  // namespace eco
