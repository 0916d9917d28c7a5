// Levels of detail of one tree (billboards and impostors come with the renderer):
//   LOD0  the full mesh: every segment, every leaf;
//   LOD1  fewer ring sides, twigs of fewer than 4 strands dropped, leaves gathered into
//         clusters of crossed cards textured with many small leaves, keeping the leaf area;
//   LOD2  a crown-volume proxy of a few hundred triangles, a star-shaped hull around the
//         leaves that keeps the silhouette, on a low-poly stem.
#pragma once

#include "model/mesh.hpp"
#include "model/skeleton.hpp"
#include "model/species.hpp"

namespace eco {

inline constexpr int kLodCount = 3;
inline constexpr int kLod1MinStrands = 4;
inline constexpr int kLod1ClusterStrands = 16;  // leaves under one such branch form a cluster
// Fraction of a cluster card covered by leaves in the cluster texture.
inline constexpr float kClusterCoverage = 0.5f;

TreeMesh buildLod(const TreeSkeleton& skeleton, const Species& species, int lod);
// The same into a mesh the caller owns (LOD0 reuses its capacity).
void buildLodInto(const TreeSkeleton& skeleton, const Species& species, int lod, TreeMesh& out);

}  // namespace eco
