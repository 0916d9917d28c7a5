#include "render/gl/ground_cover_renderer.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numbers>

#include <glm/vec4.hpp>

namespace eco {
namespace {

constexpr int kCards = 3;  // crossed at 60 degrees

// Each card's four corners: across (-0.5..0.5), up (0..1), the card's angle.
std::array<glm::vec3, 4 * kCards> tuftCorners() {
  std::array<glm::vec3, 4 * kCards> corners{};
  for (int c = 0; c < kCards; ++c) {
    const float angle = static_cast<float>(c) * std::numbers::pi_v<float> / kCards;
    corners[4 * c + 0] = {-0.5f, 0.0f, angle};
    corners[4 * c + 1] = {0.5f, 0.0f, angle};
    corners[4 * c + 2] = {0.5f, 1.0f, angle};
    corners[4 * c + 3] = {-0.5f, 1.0f, angle};
  }
  return corners;
}

std::array<std::uint32_t, 6 * kCards> tuftTriangles() {
  std::array<std::uint32_t, 6 * kCards> indices{};
  for (std::uint32_t c = 0; c < kCards; ++c) {
    const std::uint32_t v = 4 * c;
    const std::array<std::uint32_t, 6> quad{v, v + 1, v + 2, v, v + 2, v + 3};
    std::copy(quad.begin(), quad.end(), indices.begin() + 6 * c);
  }
  return indices;
}

}  // namespace

GroundCoverRenderer::GroundCoverRenderer(const Terrain& terrain)
    : cover_(terrain),
      program_(
          {{GL_VERTEX_SHADER, "ground_cover.vert"}, {GL_FRAGMENT_SHADER, "ground_cover.frag"}}) {
  const auto corners = tuftCorners();
  const auto triangles = tuftTriangles();
  corners_ = makeBuffer(std::span<const glm::vec3>(corners));
  indices_ = makeBuffer(std::span<const std::uint32_t>(triangles));
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  instances_ = GlName(GlKind::Buffer, buffer);
  vertexArray_ = makeVertexArray();
  const GLuint vao = vertexArray_.id();
  glVertexArrayVertexBuffer(vao, 0, corners_.id(), 0, sizeof(glm::vec3));
  glVertexArrayElementBuffer(vao, indices_.id());
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, 0, 0);
  glVertexArrayVertexBuffer(vao, 1, instances_.id(), 0, sizeof(Instance));
  glVertexArrayBindingDivisor(vao, 1, 1);
  const GLuint offsets[] = {offsetof(Instance, foot), offsetof(Instance, look)};
  for (GLuint a = 1; a <= 2; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, 4, GL_FLOAT, GL_FALSE, offsets[a - 1]);
    glVertexArrayAttribBinding(vao, a, 1);
  }
  atlas_ = makeTexture(makeGroundCoverAtlas(), false);
  const FieldStats range = statsOf(terrain.height_m);
  program_.set("uAltitudeRange",
               glm::vec2(static_cast<float>(range.min), static_cast<float>(range.max)));
}

std::size_t GroundCoverRenderer::draw(glm::vec3 eye, const Frustum& frustum,
                                      const GroundCoverSettings& settings) {
  const std::vector<GroundTuft> tufts = cover_.scatter(eye, frustum, settings);
  if (tufts.empty()) return 0;
  staging_.clear();
  for (const GroundTuft& t : tufts)
    staging_.push_back({glm::vec4(t.position, t.height_m),
                        glm::vec4(t.yaw, static_cast<float>(t.plant), t.variation, t.moisture)});
  if (staging_.size() > capacity_) {
    capacity_ = staging_.size() + staging_.size() / 2;
    glNamedBufferData(instances_.id(), static_cast<GLsizeiptr>(capacity_ * sizeof(Instance)),
                      nullptr, GL_STREAM_DRAW);
  }
  glNamedBufferSubData(instances_.id(), 0,
                       static_cast<GLsizeiptr>(staging_.size() * sizeof(Instance)),
                       staging_.data());
  program_.use();
  program_.set("uRadius", settings.radius_m);
  glBindTextureUnit(7, atlas_.id());
  glBindVertexArray(vertexArray_.id());
  glDisable(GL_CULL_FACE);  // the cards are seen from both sides
  glDrawElementsInstanced(GL_TRIANGLES, 6 * kCards, GL_UNSIGNED_INT, nullptr,
                          static_cast<GLsizei>(staging_.size()));
  glEnable(GL_CULL_FACE);
  return staging_.size();
}

}  // namespace eco
