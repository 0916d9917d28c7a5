#include "render/scene/wind_mesh.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtx/norm.hpp>

#include "model/strand_model.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

TEST(WindMesh, EveryLevelOfEverySpeciesKeepsItsTopologyInTheWind) {
  for (const char* name : {"beech", "maple", "pine", "shrub"}) {
    const WindLods lods = buildWindLods(test::loadNamedSpecies(name), 3, 0.5);
    EXPECT_EQ(lods.windless, 0) << name;
  }
}

TEST(WindMesh, WithoutWindTheRestPoseIsTheModelsTree) {
  const Species maple = test::loadNamedSpecies("maple");
  const WindLods lods = buildWindLods(maple, 3, 0.4);
  const std::vector<glm::vec3> exact = test::cpuPositions(maple, 0.4, {}, 0.0, 1);
  std::vector<glm::vec3> predicted;
  for (const WindPart& part : lods.lods[1].parts)
    for (const TreeVertex& v : part.vertices) predicted.push_back(test::linearised(v, {}, 2.0));
  ASSERT_EQ(predicted.size(), exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i) EXPECT_EQ(predicted[i], exact[i]);
}

TEST(WindMesh, AnyMeshersShareTheFivePosesAndTheRestPoseAloneHasNoBases) {
  const Species maple = test::loadNamedSpecies("maple");
  TreeSkeleton lodsRest;
  const WindLods lods = buildWindLods(maple, 3, 0.4, &lodsRest);
  const std::vector<SkeletonMesher> lod1 = {[&](const TreeSkeleton& skeleton, TreeMesh& mesh) {
    buildLodInto(skeleton, maple, 1, mesh);
  }};
  TreeSkeleton rest;
  const std::vector<WindMesh> withBases = buildWindMeshes(maple, 3, 0.4, lod1, nullptr, &rest);
  const std::vector<WindMesh> restOnly =
      buildWindMeshes(maple, 3, 0.4, lod1, nullptr, nullptr, false);
  ASSERT_EQ(withBases.size(), 1u);
  ASSERT_EQ(lodsRest.segments.size(), rest.segments.size());
  for (std::size_t i = 0; i < rest.segments.size(); ++i)
    EXPECT_EQ(lodsRest.segments[i].end(), rest.segments[i].end());
  EXPECT_EQ(rest.segments.size(),
            buildTree(maple, windBuildOptions(maple, 3, 0.4, {}, 0.0)).segments.size());
  const WindPart& a = lods.lods[1].parts[0];
  const WindPart& b = withBases[0].parts[0];
  const WindPart& c = restOnly[0].parts[0];
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  ASSERT_EQ(a.vertices.size(), c.vertices.size());
  bool anyBasis = false;
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    EXPECT_EQ(a.vertices[v].position, b.vertices[v].position);
    EXPECT_EQ(a.vertices[v].swaySin, b.vertices[v].swaySin);
    EXPECT_EQ(a.vertices[v].bendEast, b.vertices[v].bendEast);
    EXPECT_EQ(c.vertices[v].position, a.vertices[v].position);
    EXPECT_EQ(c.vertices[v].bendEast, glm::vec3(0.0f));
    EXPECT_EQ(c.vertices[v].swayCos, glm::vec3(0.0f));
    anyBasis = anyBasis || glm::length(a.vertices[v].bendEast) > 0.0f;
  }
  EXPECT_TRUE(anyBasis);
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
      for (const TreeVertex& v : part.vertices) predicted.push_back(test::linearised(v, wind, t));
    const test::Agreement a =
        test::agreement(lods.lods[0], predicted, test::cpuPositions(maple, age, wind, t, 0));
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
  const std::vector<glm::vec3> full =
      test::cpuPositions(beech, 0.7, {0.0, {kBendBasis_wg, 0.0}}, 0.0, 0);
  std::size_t i = 0;
  for (const WindPart& part : lods.lods[0].parts)
    for (const TreeVertex& v : part.vertices)
      ASSERT_LT(glm::distance(v.position + v.bendEast, full[i++]), 1e-4f);
}

TEST(LeanResponse, IsLinearThroughTheBasisAndTheMeasuredSamples) {
  const LeanResponse response{.bend = {2.0f, 3.0f}};  // samples at 3 and 6 w_g
  ASSERT_EQ(kBendBasis_wg, 1.0);
  ASSERT_EQ(kLeanSamples_wg[0], 3.0);
  ASSERT_EQ(kLeanSamples_wg[1], 6.0);
  EXPECT_EQ(response.basesFor({0.0f, 0.0f}), glm::vec2(0.0f));
  EXPECT_FLOAT_EQ(response.basesFor({0.5f, 0.0f}).x, 0.5f);
  EXPECT_FLOAT_EQ(response.basesFor({1.0f, 0.0f}).x, 1.0f);
  EXPECT_FLOAT_EQ(response.basesFor({2.0f, 0.0f}).x, 1.5f);
  EXPECT_FLOAT_EQ(response.basesFor({3.0f, 0.0f}).x, 2.0f);
  EXPECT_FLOAT_EQ(response.basesFor({4.5f, 0.0f}).x, 2.5f);
  EXPECT_FLOAT_EQ(response.basesFor({7.5f, 0.0f}).x, 3.5f);  // the last segment goes on
  // The direction is kept: 3 w_g toward south-west.
  const glm::vec2 bases = response.basesFor(glm::vec2(-3.0f, 3.0f) / std::sqrt(2.0f) * 1.0f);
  EXPECT_NEAR(bases.x, -2.0f / std::sqrt(2.0f), 1e-5f);
  EXPECT_NEAR(bases.y, 2.0f / std::sqrt(2.0f), 1e-5f);
  EXPECT_EQ(LeanResponse{}.basesFor({6.0f, 0.0f}).x, 6.0f);  // unmeasured: the straight line
}

// The foliage centre's east offset as drawn with `bases` multiples of bendEast, and in the
// model grown with the lean.
float foliageEast(const WindMesh& mesh, float bases) {
  const FoliageCentre centre = foliageCentre(mesh);
  return static_cast<float>(centre.position.x + bases * centre.bendEast.x);
}
float foliageEast(const Species& species, double age, double lean_wg) {
  return static_cast<float>(
      foliageCentre(buildLod(buildStrandTree(species, windBuildOptions(species, 3, age,
                                                                       {0.0, {lean_wg, 0.0}}, 0.0)),
                             species, 0))
          .x);
}

// EcoMod turns branches toward the directed vector, so a strong lean moves a crown less than
// the bases' straight line: the measured response draws the crown's centre where the model
// grows it, at the samples and between them (a pine, whose stem follows the lean most).
TEST(LeanResponse, MovesTheCrownAsFarAsTheModelGrownWithTheLean) {
  const Species pine = test::loadNamedSpecies("pine");
  TreeSkeleton rest;
  const WindLods lods = buildWindLods(pine, 3, 0.7, &rest);
  const float height = static_cast<float>(measure(rest).height_m);
  const LeanResponse response = measureLeanResponse(pine, 3, 0.7, 0.0, lods.lods[0]);
  EXPECT_LT(response.bend[0], 0.9f * 3.0f);
  EXPECT_LT(response.bend[1], 0.8f * 6.0f);
  for (float lean : {3.0f, 4.5f, 6.0f}) {
    const float exact = foliageEast(pine, 0.7, lean);
    const float drawn = foliageEast(lods.lods[0], response.basesFor({lean, 0.0f}).x);
    const float line = foliageEast(lods.lods[0], lean / static_cast<float>(kBendBasis_wg));
    EXPECT_NEAR(drawn, exact, 0.01f * height) << lean;
    EXPECT_GT(line - exact, 0.02f * height) << lean;
  }
}

}  // namespace
}  // namespace eco
