#include "render/gl/terrain_renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/scene/camera.hpp"
#include "sim/conditions/condition_maps.hpp"
#include "sim/conditions/moisture.hpp"
#include "sim/terrain_mesh.hpp"

namespace eco {
namespace {

struct TerrainVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 mapUv;
};

}  // namespace

TerrainRenderer::TerrainRenderer(const Terrain& terrain)
    : grid_(terrain.grid),
      program_({{GL_VERTEX_SHADER, "terrain.vert"}, {GL_FRAGMENT_SHADER, "terrain.frag"}}),
      shadowProgram_({{GL_VERTEX_SHADER, "terrain.vert"}, {GL_FRAGMENT_SHADER, "terrain.frag"}},
                     {"SHADOW_PASS"}) {
  const Grid& g = terrain.grid;
  const FieldStats range = statsOf(terrain.height_m);
  lowest_m_ = static_cast<float>(range.min);
  highest_m_ = static_cast<float>(range.max);
  const TerrainRim rim = terrainRim(g);
  std::vector<TerrainVertex> vertices;
  for (const DrawnVertex& v : drawnTerrainVertices(terrain, rim))
    vertices.push_back({worldFromMap(v.position), worldDirectionFromMap(v.normal), v.mapUv});
  // Triangles in square chunks of kChunkCells, each with a bounding sphere for culling.
  std::vector<std::uint32_t> indices;
  indices.reserve(static_cast<std::size_t>(g.width - 1) * (g.height - 1) * 6);
  for (int cy = 0; cy + 1 < g.height; cy += kChunkCells)
    for (int cx = 0; cx + 1 < g.width; cx += kChunkCells) {
      Chunk chunk;
      chunk.firstIndex = indices.size();
      glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
      for (int y = cy; y + 1 < g.height && y < cy + kChunkCells; ++y)
        for (int x = cx; x + 1 < g.width && x < cx + kChunkCells; ++x) {
          const std::array<std::uint32_t, 6> square = squareTriangles(g, x, y);
          indices.insert(indices.end(), square.begin(), square.end());
          for (std::uint32_t corner : square) {
            lo = glm::min(lo, vertices[corner].position);
            hi = glm::max(hi, vertices[corner].position);
          }
        }
      chunk.indexCount = static_cast<GLsizei>(indices.size() - chunk.firstIndex);
      chunk.centre = 0.5f * (lo + hi);
      chunk.radius = 0.5f * glm::length(hi - lo);
      chunks_.push_back(chunk);
    }
  // The rim around the map as one more chunk.
  Chunk edge;
  edge.firstIndex = indices.size();
  indices.insert(indices.end(), rim.triangles.begin(), rim.triangles.end());
  edge.indexCount = static_cast<GLsizei>(rim.triangles.size());
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (std::size_t i = g.cellCount(); i < vertices.size(); ++i) {
    lo = glm::min(lo, vertices[i].position);
    hi = glm::max(hi, vertices[i].position);
  }
  edge.centre = 0.5f * (lo + hi);
  edge.radius = 0.5f * glm::length(hi - lo);
  chunks_.push_back(edge);
  indexCount_ = static_cast<GLsizei>(indices.size());
  vertices_ = makeBuffer(std::span<const TerrainVertex>(vertices));
  indices_ = makeBuffer(std::span<const std::uint32_t>(indices));
  vertexArray_ = makeVertexArray();
  const GLuint vao = vertexArray_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(TerrainVertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  const GLuint offsets[] = {offsetof(TerrainVertex, position), offsetof(TerrainVertex, normal),
                            offsetof(TerrainVertex, mapUv)};
  const GLint sizes[] = {3, 3, 2};
  for (GLuint a = 0; a < 3; ++a) {
    glEnableVertexArrayAttrib(vao, a);
    glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
    glVertexArrayAttribBinding(vao, a, 0);
  }
  program_.set("uAltitudeRange", glm::vec2(lowest_m_, highest_m_));
}

void TerrainRenderer::setOverlay(const std::string& name, const Field& values) {
  const auto [lo, hi] = rampRange(name, "", statsOf(values));
  Image image(grid_.width, grid_.height);
  for (int y = 0; y < grid_.height; ++y)
    for (int x = 0; x < grid_.width; ++x) {
      const float v = values[grid_.index(x, y)];
      const double t = hi > lo ? (v - lo) / (hi - lo) : 0.5;
      // Outside the landscape (NaN) the ground shows grey.
      image.set(
          x, y,
          std::isnan(v) ? glm::vec4(0.5f, 0.5f, 0.5f, 1.0f) : glm::vec4(rampColor(name, t), 1.0f));
    }
  overlay_ = makeTexture(image, false);
}

void TerrainRenderer::setCanopyCover(const Field& cover) {
  // A linear 8-bit share (not an sRGB colour), filtered between cell centres.
  std::vector<std::uint8_t> bytes(cover.size());
  for (std::size_t c = 0; c < cover.size(); ++c)
    bytes[c] = static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(cover[c], 0.0f, 1.0f)));
  canopyCover_ = makeTextureStorage(GL_R8, grid_.width, grid_.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(canopyCover_.id(), 0, 0, 0, grid_.width, grid_.height, GL_RED,
                      GL_UNSIGNED_BYTE, bytes.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

void TerrainRenderer::setCanopyFloor(const CanopyFloor& floor) {
  static_assert(kCanopyHeightTops_m.size() == 8, "two RGBA textures of running sums");
  // Half floats, filtered between cell centres: crown areas in cell areas and linear colours.
  const std::size_t cells = floor.crownsBelow.size();
  std::vector<glm::vec4> low(cells), high(cells), colour(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    const auto& below = floor.crownsBelow[c];
    low[c] = glm::vec4(below[0], below[1], below[2], below[3]);
    high[c] = glm::vec4(below[4], below[5], below[6], below[7]);
    colour[c] = glm::vec4(floor.leafColor[c], 1.0f);
  }
  auto upload = [&](const std::vector<glm::vec4>& texels) {
    GlName texture = makeTextureStorage(GL_RGBA16F, grid_.width, grid_.height);
    glTextureSubImage2D(texture.id(), 0, 0, 0, grid_.width, grid_.height, GL_RGBA, GL_FLOAT,
                        texels.data());
    return texture;
  };
  crownsBelowLow_ = upload(low);
  crownsBelowHigh_ = upload(high);
  crownColor_ = upload(colour);
}

void TerrainRenderer::setMoisture(const Field& moisture) {
  // Half floats (F to a hundredth), filtered between cell centres; an outside cell (NaN) is fresh.
  std::vector<float> values(moisture.size());
  for (std::size_t c = 0; c < moisture.size(); ++c)
    values[c] = std::isfinite(moisture[c]) ? moisture[c] : kFreshMoisture;
  moisture_ = makeTextureStorage(GL_R16F, grid_.width, grid_.height);
  glTextureSubImage2D(moisture_.id(), 0, 0, 0, grid_.width, grid_.height, GL_RED, GL_FLOAT,
                      values.data());
}

std::size_t TerrainRenderer::draw(const Frustum& frustum, bool shadowPass,
                                  float unresolvedPerMetre) const {
  counts_.clear();
  offsets_.clear();
  std::size_t triangles = 0;
  for (const Chunk& chunk : chunks_)
    if (frustum.intersectsSphere(chunk.centre, chunk.radius)) {
      counts_.push_back(chunk.indexCount);
      offsets_.push_back(reinterpret_cast<const void*>(chunk.firstIndex * sizeof(std::uint32_t)));
      triangles += chunk.indexCount / 3;
    }
  if (counts_.empty()) return 0;
  const Program& program = shadowPass ? shadowProgram_ : program_;
  program.use();
  program.set("uHasOverlay", hasOverlay() ? 1 : 0);
  if (hasOverlay()) glBindTextureUnit(3, overlay_.id());
  program.set("uHasCanopyCover", canopyCover_ ? 1 : 0);
  if (canopyCover_) glBindTextureUnit(6, canopyCover_.id());
  program.set("uHasMoisture", moisture_ ? 1 : 0);
  if (moisture_) glBindTextureUnit(8, moisture_.id());
  const bool unresolved = crownColor_ && unresolvedPerMetre > 0.0f;
  program.set("uUnresolvedPerMetre", unresolved ? unresolvedPerMetre : 0.0f);
  if (unresolved) {
    glBindTextureUnit(10, crownsBelowLow_.id());
    glBindTextureUnit(11, crownsBelowHigh_.id());
    glBindTextureUnit(12, crownColor_.id());
  }
  glBindVertexArray(vertexArray_.id());
  glMultiDrawElements(GL_TRIANGLES, counts_.data(), GL_UNSIGNED_INT, offsets_.data(),
                      static_cast<GLsizei>(counts_.size()));
  return triangles;
}

}  // namespace eco
