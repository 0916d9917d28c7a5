// Full-detail tree meshes from a skeleton: generalised cylinders along branch chains
// (Tankard, section 3.2.3.3.1.2) and leaf cards or needles.
//
// A chain starts at the base trunk or at a minor sub-branch and follows major sub-branches
// to a tip. Consecutive segments of a chain share one ring of vertices, so a branch runs
// smoothly into its major child without holes or cracks; a minor branch's first ring sits
// at the joint, inside its parent's wood. Rings are oriented by parallel transport so tubes
// do not twist.
#pragma once

#include "model/mesh/mesh.hpp"
#include "model/skeleton.hpp"
#include "model/species.hpp"

namespace eco {

struct MeshOptions {
  int maxSides = 8;    // ring sides of the thickest chain (the trunk)
  int minSides = 3;    // ring sides of the thinnest twigs
  int minStrands = 1;  // segments with fewer strands are left out (twig dropping)
  bool leaves = true;
  LeafShape leafShape = LeafShape::Broadleaf;
};

// Width of a leaf card relative to its length, per shape.
float leafCardAspect(LeafShape shape);
inline constexpr float kNeedleAspect = 0.06f;

// Appends a quad from `base` along `along` (v from 0 at the base to 1 at the tip); its
// front face looks along across x along.
void addCard(MeshPart& part, glm::vec3 base, glm::vec3 along, glm::vec3 across, float length,
             float width);

// Appends the tube mesh of every chain to `bark`.
void meshBranches(const TreeSkeleton& skeleton, const MeshOptions& options, MeshPart& bark);
// Appends one card per leaf (two crossed narrow cards per needle).
void meshLeaves(const TreeSkeleton& skeleton, LeafShape shape, MeshPart& cards, MeshPart& needles);

TreeMesh meshTree(const TreeSkeleton& skeleton, const MeshOptions& options);
// The same into a mesh the caller owns, reusing the capacity of its parts.
void meshTreeInto(const TreeSkeleton& skeleton, const MeshOptions& options, TreeMesh& out);

}  // namespace eco
