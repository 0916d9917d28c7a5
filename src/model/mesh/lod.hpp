// Levels of detail of one tree (billboards and impostors come with the renderer):
//   LOD0  the full mesh: every segment, every leaf;
//   LOD1  fewer ring sides, twigs of fewer than 4 strands dropped (strand model only);
//         broadleaves keep every leaf card of LOD0, while conifers' needles (hundreds of
//         thousands of cards) under each branch of at least 2 strands are gathered into a
//         cluster of crossed cards textured with many needles, keeping the visible needle
//         area (card area times the opaque fraction of its texture);
//   LOD2  a crown-volume proxy of a few hundred triangles, a star-shaped hull around the
//         leaves that keeps the silhouette, on a low-poly stem.
#pragma once

#include "model/mesh/mesh.hpp"
#include "model/skeleton.hpp"
#include "model/species.hpp"

namespace eco {

inline constexpr int kLodCount = 3;
inline constexpr int kLod1MinStrands = 4;
// Needles under one branch of this many strands form a cluster. Clusters under branches of 2
// strands rather than 4 measured nearer LOD0 (bench/fidelity_bench, 10,000 planted trees,
// when broadleaves were clustered too: balanced `low` 13.9 -> 13.1 of 255, high `low` 5.8 ->
// 5.6) for a fifth more LOD1 triangles; under single strands (1) a little nearer still for
// twice that.
inline constexpr int kLod1ClusterStrands = 2;

// Whether a species bears needles, which LOD1 gathers into clusters (broadleaves it keeps).
bool bearsNeedles(const Species& species);
// Visible (opaque) area of one LOD0 leaf of the species, m^2.
float visibleLeafArea(const Species& species, float size_m);

// maxSides: ring sides of the stem at LOD0 (LOD1 uses at most 5, never more than this).
inline constexpr int kDefaultMaxSides = 8;

TreeMesh buildLod(const TreeSkeleton& skeleton, const Species& species, int lod,
                  int maxSides = kDefaultMaxSides);
// The same into a mesh the caller owns (LOD0 reuses its capacity).
void buildLodInto(const TreeSkeleton& skeleton, const Species& species, int lod, TreeMesh& out,
                  int maxSides = kDefaultMaxSides);

}  // namespace eco
