// TreeSkeleton: the common currency of every tree generator (DESIGN.md). Meshing, levels of
// detail, exporters and (later) the renderer and ray tracer read only this.
// Coordinates: metres, y up, x east, z south; the stem base is at the origin.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace eco {

struct BranchSegment {
  glm::vec3 start{0.0f};  // world position of the segment's base
  glm::mat3 frame{1.0f};  // worldFromBranch rotation; column 1 (y) is the branch axis
  float length_m = 0.0f;
  float startRadius_m = 0.0f;
  float endRadius_m = 0.0f;      // equals the start radius of the major child, so tubes join
  std::int32_t parent = -1;      // index into segments; -1 for the base trunk
  bool continuesParent = false;  // the major sub-branch: same Gravelius order as the parent
  std::int16_t gravelius = 0;
  std::int16_t weibull = 0;
  std::int32_t strands = 1;  // S_0
  float windPhaseX = 0.0f;   // R_x, R_z of the branch node at this segment's tip, radians
  float windPhaseZ = 0.0f;
  // How the segment hangs from its parent at rest, in the order of Algorithm 1 (Zamuda et
  // al.): in the parent's frame it turns by gravimorphism toward the down vertical, by
  // `twist` (the phyllotaxis alpha_p), then by the sway about x and by bend + sway about z.
  // model/wind.hpp poses frame and start from these; the generators fill them.
  glm::mat3 twist{1.0f};
  double bend_deg = 0.0;           // the branching angle: +alpha_1 (major) or -alpha_2 (minor)
  double gravimorphism_deg = 0.0;  // alpha_m of the parent's split
  // Where it starts: at its parent's tip, or `offset_parent` from the parent's start in the
  // parent's frame (an L-system may start a branch anywhere).
  bool atParentTip = true;
  glm::vec3 offset_parent{0.0f};

  glm::vec3 axis() const { return frame[1]; }
  glm::vec3 end() const { return start + frame[1] * length_m; }
  bool isTerminal() const { return strands == 1; }
};

enum class LeafKind : std::uint8_t { Card, Needle };

struct Leaf {
  glm::vec3 position{0.0f};               // where the petiole attaches
  glm::vec3 direction{0.0f, 1.0f, 0.0f};  // unit, from the base toward the tip of the blade
  glm::vec3 normal{0.0f, 0.0f, 1.0f};     // unit, the side that faces the light
  float size_m = 0.0f;                    // blade length
  std::int32_t segment = -1;              // the terminal segment that carries it
  LeafKind kind = LeafKind::Card;
};

struct TreeSkeleton {
  std::vector<BranchSegment> segments;  // parents always come before their children
  std::vector<Leaf> leaves;
};

// Measurements shared by `ecoforest tree --stats`, the tests and the ecosystem.
struct SkeletonMeasures {
  std::size_t segments = 0;
  std::size_t terminalSegments = 0;
  int maxGravelius = 0;
  int maxWeibull = 0;
  double height_m = 0.0;         // highest point of wood or leaf above the base
  double crownRadius_m = 0.0;    // largest horizontal distance of wood or leaf from the stem axis
  double trunkDiameter_m = 0.0;  // diameter of the base segment
};

SkeletonMeasures measure(const TreeSkeleton& skeleton);

// Fills every segment's joint (twist and offset) from the frames and starts a generator
// built at rest, for a generator that places segments directly (the L-system turtle).
void deriveJoints(TreeSkeleton& skeleton);

}  // namespace eco
