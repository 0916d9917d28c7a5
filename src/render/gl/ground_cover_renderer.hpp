// Draws the ground cover (render/scene/ground_cover.hpp): each frame the tufts near the
// camera are scattered and drawn as instances of three crossed, alpha-tested cards.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>

#include "render/gl/gl_objects.hpp"
#include "render/gl/shader.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/ground_cover.hpp"
#include "sim/terrain.hpp"

namespace eco {

class GroundCoverRenderer {
 public:
  // The terrain must outlive the renderer.
  explicit GroundCoverRenderer(const Terrain& terrain);

  GroundCover& cover() { return cover_; }

  // Scatters the tufts within the settings' radius of `eye` in the frustum and draws them
  // (the frame's uniforms bound); returns how many were drawn.
  std::size_t draw(glm::vec3 eye, const Frustum& frustum, const GroundCoverSettings& settings);

 private:
  struct Instance {
    glm::vec4 foot;  // xyz world, w height
    glm::vec4 look;  // yaw, plant, variation, moisture
  };
  GroundCover cover_;
  Program program_;
  GlName corners_, indices_, instances_, vertexArray_, atlas_;
  std::size_t capacity_ = 0;
  std::vector<Instance> staging_;
};

}  // namespace eco
