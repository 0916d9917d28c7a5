// Sky light inside a crown (ambient occlusion from the tree's own foliage): the share of the
// sky's diffuse light that reaches a point through the leaves around it. Inner leaves,
// the stem inside the crown and the lower side of a dense crown are darker than its outer
// shell, as in a real tree, where a leaf deep in a beech crown sees a few per cent of the
// sky. Computed once per tree type from its skeleton's leaves, so every level of detail
// and the impostors share the same shade.
//
// The leaves' visible area (LOD0's, visibleLeafArea) is binned into a grid of cubic cells
// over the crown, as a leaf area density a (m^2/m^3). The sky visibility at a cell centre is
// the cosine-weighted mean, over 16 directions of the upper hemisphere, of Beer-Lambert's
// transmittance exp(-G * sum a ds) along each direction out of the grid, with G = 0.5 (the
// projection of randomly oriented leaves, Ross 1981). A point takes the trilinear blend of
// the cell centres around it.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "model/skeleton.hpp"
#include "model/species.hpp"

namespace eco {

struct WindMesh;

class CrownShade {
 public:
  CrownShade(const TreeSkeleton& tree, const Species& species);

  // 0..1: the share of the open sky's diffuse light reaching `point` (tree frame, metres).
  float skyVisibility(glm::vec3 point) const;

  static constexpr int kMaxCells = 16;            // along the crown's longest side
  static constexpr float kLeafProjection = 0.5f;  // G of randomly oriented leaves
  static constexpr int kDirections = 16;

 private:
  std::size_t indexOf(glm::ivec3 cell) const;  // x fastest
  // The cell's visibility; a cell off the grid reads the nearest border cell.
  float cellAt(int x, int y, int z) const;

  glm::vec3 origin_{0.0f};  // the corner of cell (0, 0, 0)
  float cell_m_ = 1.0f;
  glm::ivec3 size_{0};
  std::vector<float> visibility_;  // at cell centres, x fastest
};

// Sets every vertex's sky visibility from the crown's shade.
void shadeVertices(WindMesh& mesh, const CrownShade& shade);

}  // namespace eco
