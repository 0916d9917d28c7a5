#include "render/wind_mesh.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtx/norm.hpp>

#include "model/strand_model.hpp"
#include "render/forest_renderer.hpp"
#include "render/frame_uniforms.hpp"
#include "render/shader.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// The linearised wind of wind_mesh.hpp, as the shader evaluates it (gust 0).
glm::vec3 linearised(const TreeVertex& v, const TreeWind& wind, double t) {
  const float sway = static_cast<float>(wind.sway_ws / kSwayBasis_ws);
  return v.position +
         sway * (static_cast<float>(std::sin(t)) * v.swaySin +
                 static_cast<float>(std::cos(t)) * v.swayCos) +
         static_cast<float>(wind.directed.x / kBendBasis_wg) * v.bendEast +
         static_cast<float>(wind.directed.y / kBendBasis_wg) * v.bendSouth;
}

std::vector<glm::vec3> cpuPositions(const Species& species, double age, const TreeWind& wind,
                                    double t, int lod) {
  const TreeMesh mesh =
      buildLod(buildStrandTree(species, windBuildOptions(species, 3, age, wind, t)), species, lod);
  std::vector<glm::vec3> positions;
  for (const MeshPart& part : mesh.parts)
    positions.insert(positions.end(), part.positions.begin(), part.positions.end());
  return positions;
}

struct Agreement {
  float rmsError = 0.0f;
  float rmsDisplacement = 0.0f;
  float tipError = 0.0f, tipDisplacement = 0.0f;  // the highest vertex of the rest pose
};

Agreement agreement(const WindMesh& rest, const std::vector<glm::vec3>& predicted,
                    const std::vector<glm::vec3>& exact) {
  Agreement a;
  std::size_t i = 0, tip = 0;
  float highest = -1.0f;
  for (const WindPart& part : rest.parts)
    for (const TreeVertex& v : part.vertices) {
      a.rmsError += glm::distance2(predicted[i], exact[i]);
      a.rmsDisplacement += glm::distance2(v.position, exact[i]);
      if (v.position.y > highest) highest = v.position.y, tip = i;
      if (i == tip) {
        a.tipError = glm::distance(predicted[i], exact[i]);
        a.tipDisplacement = glm::distance(v.position, exact[i]);
      }
      ++i;
    }
  a.rmsError = std::sqrt(a.rmsError / i);
  a.rmsDisplacement = std::sqrt(a.rmsDisplacement / i);
  return a;
}

TEST(WindMesh, EveryLevelOfEverySpeciesKeepsItsTopologyInTheWind) {
  for (const char* name : {"beech", "maple", "pine", "shrub"}) {
    const WindLods lods = buildWindLods(test::loadNamedSpecies(name), 3, 0.5);
    EXPECT_EQ(lods.windless, 0) << name;
  }
}

TEST(WindMesh, WithoutWindTheRestPoseIsTheModelsTree) {
  const Species maple = test::loadNamedSpecies("maple");
  const WindLods lods = buildWindLods(maple, 3, 0.4);
  const std::vector<glm::vec3> exact = cpuPositions(maple, 0.4, {}, 0.0, 1);
  std::vector<glm::vec3> predicted;
  for (const WindPart& part : lods.lods[1].parts)
    for (const TreeVertex& v : part.vertices) predicted.push_back(linearised(v, {}, 2.0));
  ASSERT_EQ(predicted.size(), exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i) EXPECT_EQ(predicted[i], exact[i]);
}

// The linearised sway against the CPU model at several times: exact at t = 0 and pi / 2 by
// construction; in between the error is second order in the branch angles, a few per cent
// of the displacement for winds of this strength.
TEST(WindMesh, LinearisedSwayFollowsTheModelThroughAPeriod) {
  const Species maple = test::loadNamedSpecies("maple");
  const double age = 0.6;
  const WindLods lods = buildWindLods(maple, 3, age);
  const TreeWind wind{2.0, {0.0, 0.0}};
  for (double t : {0.0, 0.7, 1.5708, 2.4, 4.0, 5.5}) {
    std::vector<glm::vec3> predicted;
    for (const WindPart& part : lods.lods[0].parts)
      for (const TreeVertex& v : part.vertices) predicted.push_back(linearised(v, wind, t));
    const Agreement a = agreement(lods.lods[0], predicted, cpuPositions(maple, age, wind, t, 0));
    EXPECT_GT(a.tipDisplacement, 0.05f) << "t=" << t;  // the wind does move the tree
    EXPECT_LT(a.rmsError, 0.1f * a.rmsDisplacement + 0.005f) << "t=" << t;
    EXPECT_LT(a.tipError, 0.08f * a.tipDisplacement + 0.01f) << "t=" << t;
  }
}

// The horizontal bend bases (a renderer extension, docs/rendering.md): the model's tree under
// a horizontal wind of the basis strength, exactly; a wind toward east moves the crown east
// and one toward south moves it south, and half the wind bends about half as far.
TEST(WindMesh, BendBasesLeanTheCrownDownwind) {
  const Species beech = test::loadNamedSpecies("beech");
  const WindLods lods = buildWindLods(beech, 3, 0.7);
  glm::vec3 east(0.0f), south(0.0f);
  float highest = -1.0f;
  for (const WindPart& part : lods.lods[0].parts)
    for (const TreeVertex& v : part.vertices)
      if (v.position.y > highest) highest = v.position.y, east = v.bendEast, south = v.bendSouth;
  EXPECT_GT(east.x, 0.02f);
  EXPECT_GT(east.x, 3.0f * std::abs(east.z));
  EXPECT_GT(south.z, 0.02f);
  EXPECT_GT(south.z, 3.0f * std::abs(south.x));
  const std::vector<glm::vec3> full = cpuPositions(beech, 0.7, {0.0, {kBendBasis_wg, 0.0}}, 0.0, 0);
  std::size_t i = 0;
  for (const WindPart& part : lods.lods[0].parts)
    for (const TreeVertex& v : part.vertices)
      ASSERT_LT(glm::distance(v.position + v.bendEast, full[i++]), 1e-4f);
}

// The vertex shader itself, read back with transform feedback: its displaced vertices (the
// tree frame) against the CPU skeleton's mesh at the same t.
TEST(WindMesh, TheVertexShaderSwaysLikeTheCpuSkeleton) {
  test::useHeadlessGl();
  const RenderTarget target = RenderTarget::create(16, 16);  // draws need a framebuffer
  target.bind();
  const Species maple = test::loadNamedSpecies("maple");
  const double age = 0.6, t = 2.4;
  const TreeWind wind{2.0, {0.0, 0.0}};
  const WindLods lods = buildWindLods(maple, 3, age);
  const WindMesh& mesh = lods.lods[0];
  std::vector<PackedTreeVertex> vertices;  // as the renderer uploads them
  for (const WindPart& part : mesh.parts)
    for (const TreeVertex& v : part.vertices) vertices.push_back(packVertex(v));

  const Program program({{GL_VERTEX_SHADER, "tree.vert"}}, {"FEEDBACK"}, {"fbLocal"});
  FrameUniformBuffer uniforms;
  FrameUniforms u;
  u.camera.w = static_cast<float>(t);
  u.wind = glm::vec4(0.0f, 0.0f, 2.0f, 0.0f);
  uniforms.upload(u);
  const GlName vertexBuffer = makeBuffer(std::span<const PackedTreeVertex>(vertices));
  // Yaw 0, scale 1, phase 0: the tree frame is the world frame.
  const InstanceAttributes instance{glm::vec4(0.0f), glm::vec4(1, 1, 0, 0), glm::vec4(1.0f)};
  const GlName instanceBuffer = makeBuffer(&instance, sizeof(instance));
  const GlName output = makeBuffer(nullptr, vertices.size() * sizeof(glm::vec3), GL_MAP_READ_BIT);
  const GlName vao = makeVertexArray();
  setTreeVertexLayout(vao.id());
  setInstanceLayout(vao.id());
  glVertexArrayVertexBuffer(vao.id(), 0, vertexBuffer.id(), 0, sizeof(PackedTreeVertex));
  glVertexArrayVertexBuffer(vao.id(), 1, instanceBuffer.id(), 0, sizeof(InstanceAttributes));

  program.use();
  glBindVertexArray(vao.id());
  glEnable(GL_RASTERIZER_DISCARD);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, output.id());
  glBeginTransformFeedback(GL_POINTS);
  glDrawArraysInstanced(GL_POINTS, 0, static_cast<GLsizei>(vertices.size()), 1);
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  std::vector<glm::vec3> shaded(vertices.size());
  glGetNamedBufferSubData(output.id(), 0, shaded.size() * sizeof(glm::vec3), shaded.data());
  checkGl("transform feedback");

  const Agreement a = agreement(mesh, shaded, cpuPositions(maple, age, wind, t, 0));
  EXPECT_GT(a.tipDisplacement, 0.05f);
  EXPECT_LT(a.tipError, 0.08f * a.tipDisplacement + 0.01f)
      << "tip moved " << a.tipDisplacement << " m, shader off by " << a.tipError << " m";
  EXPECT_LT(a.rmsError, 0.1f * a.rmsDisplacement + 0.005f);
}

}  // namespace
}  // namespace eco
