#include "model/tree_generator.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "model/mesh/lod.hpp"
#include "model/strand_model.hpp"
#include "test_support.hpp"

namespace eco {
namespace {

TEST(TreeGenerator, StrandSpeciesBuildTheStrandModel) {
  const Species beech = test::loadNamed("beech");
  TreeBuildOptions options;
  options.seed = 3;
  const TreeSkeleton a = buildTree(beech, options);
  const TreeSkeleton b = buildStrandTree(beech, options);
  ASSERT_EQ(a.segments.size(), b.segments.size());
  EXPECT_EQ(a.segments.back().start, b.segments.back().start);
}

TEST(TreeGenerator, LSystemSpeciesGrowFromTheirGrammar) {
  const Species birch = test::loadNamed("birch");
  ASSERT_EQ(birch.generator, TreeGenerator::LSystem);
  EXPECT_EQ(birch.lsystem.iterations, 6);
  TreeBuildOptions options;
  const TreeSkeleton mature = buildTree(birch, options);
  const SkeletonMeasures m = measure(mature);
  EXPECT_GT(m.height_m, 15.0);  // about 22 m: turtle units times unit_m
  EXPECT_LT(m.height_m, 30.0);
  EXPECT_EQ(mature.leaves.size(), 3u * 729u);  // three leaves on each of 3^6 apices
  options.age = 0.5;
  const TreeSkeleton young = buildTree(birch, options);
  EXPECT_LT(young.segments.size(), mature.segments.size() / 5);
  EXPECT_LT(measure(young).height_m, m.height_m);
}

TEST(TreeGenerator, EachSeedIsAnotherIndividual) {
  const Species birch = test::loadNamed("birch");
  TreeBuildOptions options;
  options.seed = 1;
  const TreeSkeleton one = buildTree(birch, options);
  const TreeSkeleton again = buildTree(birch, options);
  options.seed = 2;
  const TreeSkeleton two = buildTree(birch, options);
  ASSERT_EQ(one.segments.size(), two.segments.size());  // same topology: random angles
  EXPECT_EQ(one.segments.back().end(), again.segments.back().end());
  EXPECT_NE(one.segments.back().end(), two.segments.back().end());
}

TEST(TreeGenerator, LSystemTreesHaveEveryLevelOfDetail) {
  const Species birch = test::loadNamed("birch");
  const TreeSkeleton tree = buildTree(birch, {});
  std::size_t previous = SIZE_MAX;
  for (int lod = 0; lod < kLodCount; ++lod) {
    const TreeMesh mesh = buildLod(tree, birch, lod);
    EXPECT_GT(mesh.triangleCount(), 0u) << lod;
    EXPECT_LT(mesh.triangleCount(), previous) << lod;
    previous = mesh.triangleCount();
  }
  TreeBuildOptions leafless;
  leafless.leaves = false;
  EXPECT_TRUE(buildTree(birch, leafless).leaves.empty());
}

TEST(TreeGenerator, IterationsScaleWithAge) {
  EXPECT_EQ(lsystemIterationsForAge(6, 1.0), 6);
  EXPECT_EQ(lsystemIterationsForAge(6, 0.5), 3);
  EXPECT_EQ(lsystemIterationsForAge(6, 0.0), 1);
  EXPECT_EQ(lsystemIterationsForAge(10, 0.26), 3);
}

TEST(TreeGenerator, ScalingTurnsTurtleUnitsIntoMetres) {
  TreeSkeleton t;
  t.segments.push_back({{1, 2, 3}, glm::mat3(1.0f), 2.0f, 0.5f, 0.25f});
  t.leaves.push_back({{0, 4, 0}, {0, 1, 0}, {0, 0, 1}, 1.0f, 0});
  scaleSkeleton(t, 0.5f);
  EXPECT_EQ(t.segments[0].start, glm::vec3(0.5f, 1.0f, 1.5f));
  EXPECT_FLOAT_EQ(t.segments[0].length_m, 1.0f);
  EXPECT_FLOAT_EQ(t.segments[0].endRadius_m, 0.125f);
  EXPECT_EQ(t.leaves[0].position, glm::vec3(0, 2, 0));
  EXPECT_FLOAT_EQ(t.leaves[0].size_m, 0.5f);
}

TEST(TreeGenerator, SpeciesFilesNameAValidGenerator) {
  const auto bad = test::writeTemporary("bad_generator", "name = \"x\"\ngenerator = \"bogus\"\n");
  try {
    loadSpecies(bad);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":2: generator: unknown generator 'bogus'"),
              std::string::npos)
        << e.what();
  }
  const auto missing = test::writeTemporary(
      "missing_grammar", "name = \"x\"\ngenerator = \"lsystem\"\n[lsystem]\nfile = \"no.lsys\"\n");
  EXPECT_THROW(loadSpecies(missing), InputError);
  const auto noTable = test::writeTemporary("no_table", "name = \"x\"\ngenerator = \"lsystem\"\n");
  EXPECT_THROW(loadSpecies(noTable), InputError);
  const auto woodless = test::writeTemporary(
      "woodless", "name = \"x\"\ngenerator = \"lsystem\"\n[lsystem]\nfile = \"" +
                      std::string(ECOFOREST_DATA_DIR) + "/lsystems/green_example.lsys\"\n");
  try {
    loadSpecies(woodless);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lsystem.file: the grammar draws no wood"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace eco
