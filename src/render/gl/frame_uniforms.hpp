// The uniform block every shader reads (FrameBlock in shaders/common.glsl), and the buffer
// that holds it at binding 0. std140: only vec4 and mat4 members, in the shader's order.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "render/gl/gl_objects.hpp"
#include "render/scene/shadow_cascades.hpp"

namespace eco {

struct FrameUniforms {
  glm::mat4 viewProj{1.0f};
  glm::mat4 lightViewProj{1.0f};  // the shadow pass being drawn: its cascade's
  glm::mat4 inverseViewProj{1.0f};
  glm::mat4 shadowCascades[kShadowCascades]{};   // every cascade's, nearest first: lookups
  glm::vec4 camera{0.0f};                        // xyz eye; w wind time
  glm::vec4 toSun{0.0f, 1.0f, 0.0f, 0.0f};       // w: 1 when the shadow map is used
  glm::vec4 sunColor{1.0f};                      // w: fog density per metre
  glm::vec4 skyZenith{0.0f};                     // w: the haze's base altitude (m)
  glm::vec4 skyHorizon{0.0f, 0.0f, 0.0f, 1.0f};  // w: the haze's scale height (m)
  glm::vec4 ambient{0.0f};
  glm::vec4 wind{0.0f};  // directed (east, south) / kBendBasis_wg, sway / kSwayBasis_ws, gust
};

class FrameUniformBuffer {
 public:
  FrameUniformBuffer()
      : buffer_(makeBuffer(nullptr, sizeof(FrameUniforms), GL_DYNAMIC_STORAGE_BIT)) {}
  void upload(const FrameUniforms& u) const {
    glNamedBufferSubData(buffer_.id(), 0, sizeof(FrameUniforms), &u);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, buffer_.id());
  }

 private:
  GlName buffer_;
};

}  // namespace eco
