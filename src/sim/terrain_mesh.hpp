// The one triangulation of a heightmap: a vertex at every cell centre and two triangles per
// grid square, split along the square's diagonal from its north-east to its south-west
// corner, counter-clockwise seen from above. Terrain::altitudeAt interpolates on these
// triangles, both Embree scenes (sunniness, canopy light) trace them, and the renderer and
// the glTF export draw them, so a plant stands exactly on the ground every one of them sees.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/terrain.hpp"

namespace eco {

// The corner cells of the two triangles of the square whose north-west corner is cell
// (x, y): (NW, SW, NE) and (NE, SW, SE), as indices into the grid's cells.
std::array<std::uint32_t, 6> squareTriangles(const Grid& grid, int x, int y);
// Every square's triangles, square by square in row-major order: 6 indices per square.
std::vector<std::uint32_t> terrainTriangles(const Grid& grid);

// The vertex of cell (x, y) in the map frame (east, north, altitude).
glm::vec3 cellPosition(const Terrain& terrain, int x, int y);

// What is drawn of the triangles' flat continuation past the edges: a rim of half a cell
// out to the edge cells' outer sides, so that the drawn terrain covers every cell and the
// plants of edge cells stand on it (the renderer and the glTF export draw it; rays need
// it not). Rim vertex i is cell (x, y) moved by (east, north) metres, with the cell's height
// and normal; the triangles index the grid's cells first, then cellCount() + i.
struct RimVertex {
  int x = 0, y = 0;
  float east_m = 0.0f, north_m = 0.0f;
  // Its position in the map frame, and its texture coordinate on the map ([0, 1]^2 over the
  // cells' extent, v growing south).
  glm::vec3 position(const Terrain& terrain) const;
  glm::vec2 mapUv(const Grid& grid) const;
};
struct TerrainRim {
  std::vector<RimVertex> vertices;
  std::vector<std::uint32_t> triangles;  // counter-clockwise seen from above
};
TerrainRim terrainRim(const Grid& grid);

// Every vertex the renderer and the glTF export draw, in the order terrainTriangles and the
// rim's triangles index them: the cells' row by row, then the rim's; in the map frame, with
// the terrain's normal and the map coordinate (RimVertex::mapUv).
struct DrawnVertex {
  glm::vec3 position;
  glm::dvec3 normal;
  glm::vec2 mapUv;
};
std::vector<DrawnVertex> drawnTerrainVertices(const Terrain& terrain, const TerrainRim& rim);

// The height gradient of a cell: dz/dx east and dz/dy north, metres per metre, by Horn's
// (1981) third-order finite differences on the 3 x 3 neighbourhood with separate east-west
// and north-south cell sizes. Past the edges the surface is continued linearly, so edge
// cells of a plane get the plane's exact gradient.
struct Gradient {
  double east = 0.0;
  double north = 0.0;
};
Gradient terrainGradient(const Terrain& terrain, int x, int y);
// The unit normal of cell (x, y) in the map frame, from its gradient: what slope and aspect
// describe and what the renderer and the glTF export shade.
glm::dvec3 terrainNormal(const Terrain& terrain, int x, int y);

// The altitude at a map position on the triangles (the edge cells' triangles continued
// flat past the edges).
float altitudeOnTriangles(const Terrain& terrain, double east_m, double north_m);

}  // namespace eco
