#include "render/scene/forest.hpp"

#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "render/scene/camera.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

TEST(Forest, ASnapshotPlantStandsAtItsPlaceAtItsHeight) {
  const TreeLibrary& library = test::smallLibrary();
  TreeSnapshot snapshot;
  snapshot.speciesNames = {"maple", "beech"};
  snapshot.trees.push_back({.id = 1,
                            .species = 0,
                            .east_m = 10,
                            .north_m = 20,
                            .ground_m = 300,
                            .age_years = 30,
                            .height_m = 12.0f,
                            .crownRadius_m = 3.0f,
                            .vigor = 0.8f,
                            .variantSeed = 5});
  snapshot.trees.push_back({.id = 2,
                            .species = 1,
                            .east_m = 50,
                            .north_m = 5,
                            .ground_m = 310,
                            .age_years = 3,
                            .height_m = 0.3f,
                            .vigor = 1.0f,
                            .variantSeed = 9});
  const Forest forest = forestFromSnapshot(snapshot, library, "run");
  ASSERT_EQ(forest.size(), 2u);
  EXPECT_EQ(forest.position[0], worldFromMap(10, 20, 300));
  EXPECT_EQ(library.type(forest.type[0]).species, 1);  // maple is the library's second
  EXPECT_EQ(library.type(forest.type[1]).species, 0);
  for (std::size_t i = 0; i < 2; ++i) {
    const float height = forest.scaleY[i] * library.type(forest.type[i]).height_m;
    EXPECT_NEAR(height, snapshot.trees[i].height_m, 1e-4f);
    EXPECT_GE(forest.scaleXZ[i], 0.7f * forest.scaleY[i] - 1e-6f);
    EXPECT_LE(forest.scaleXZ[i], 1.4f * forest.scaleY[i] + 1e-6f);
  }
}

// A beech at a forest edge with the light from the east, and half its height a clear bole.
TreeSnapshot edgeTree() {
  TreeSnapshot snapshot;
  snapshot.speciesNames = {"beech"};
  snapshot.trees.push_back({.id = 1,
                            .species = 0,
                            .age_years = 120,
                            .height_m = 30.0f,
                            .crownRadius_m = 5.0f,
                            .crownBase_m = 15.0f,
                            .vigor = 0.8f,
                            .variantSeed = 5,
                            .site = {.light = {0.5, 0.0}, .wind = {0.0, 0.0}}});
  return snapshot;
}

TEST(Forest, WithShapingATreeLeansTowardItsLightAndTakesItsCrownClass) {
  const TreeLibrary& library = test::shapedLibrary();
  TreeSnapshot snapshot = edgeTree();
  Forest forest = forestFromSnapshot(snapshot, library, "run");
  const TreeType& type = library.type(forest.type[0]);
  EXPECT_EQ(type.crownClass, library.crownClassFor(0.5));
  const glm::vec2 lean(shapingLean({.light = {0.5, 0.0}}));
  EXPECT_GT(lean.x, 0.0f);
  EXPECT_EQ(forest.lean[0], type.leanResponse.basesFor(lean));
  // The map's north is the tree frame's -z (south positive): light from the north.
  snapshot.trees[0].site.light = {0.0, 0.5};
  forest = forestFromSnapshot(snapshot, library, "run");
  EXPECT_NEAR(forest.lean[0].x, 0.0f, 1e-6f);
  EXPECT_LT(forest.lean[0].y, 0.0f);
}

TEST(Forest, WithoutShapingEveryTreeStandsUprightInTheOpenGrownCrownClass) {
  LibrarySettings settings = LibrarySettings::shaped(false);
  settings.variants = 1;
  settings.ageClasses = {1.0};
  const TreeLibrary library({test::namedLibrarySpecies("beech")}, settings);
  const Forest forest = forestFromSnapshot(edgeTree(), library, "run");
  EXPECT_EQ(library.type(forest.type[0]).crownClass, 0);
  EXPECT_EQ(forest.lean[0], glm::vec2(0.0f));
}

TEST(Forest, ASnapshotBuildsTheTypesItsTreesDrawAndNoOther) {
  const TreeLibrary library(
      {test::namedLibrarySpecies("beech"), test::namedLibrarySpecies("maple")},
      LibrarySettings{.variants = 2, .ageClasses = {0.4, 1.0}});
  EXPECT_EQ(library.builtTypeCount(), 0);
  TreeSnapshot snapshot;
  snapshot.speciesNames = {"maple"};
  for (std::uint64_t id = 1; id <= 3; ++id)
    snapshot.trees.push_back({.id = id, .species = 0, .height_m = 0.3f, .variantSeed = 4});
  const Forest forest = forestFromSnapshot(snapshot, library, "run");
  const std::vector<int> drawn{library.typeIndex(1, 0, 0)};  // seed 4: variant 0 of 2
  EXPECT_EQ(typesOf(forest), drawn);
  EXPECT_EQ(library.builtTypeCount(), 1);
  library.type(library.typeIndex(0, 1, 1));  // any other type: built when it is asked for
  EXPECT_EQ(library.builtTypeCount(), 2);
}

TEST(Forest, TypesOfListsEachTypeAndEachBlendTypeOnceInOrder) {
  Forest forest;
  forest.resize(4);
  forest.type = {3, 1, 3, 0};
  forest.blendType[1] = 5;
  forest.blendType[3] = 1;
  EXPECT_EQ(typesOf(forest), (std::vector<int>{0, 1, 3, 5}));
}

TEST(Forest, AppendCopiesEveryArrayOfATree) {
  const TreeLibrary& library = test::smallLibrary();
  Forest all;
  for (int i = 0; i < 3; ++i)
    all.add(library, library.typeIndex(i % 2, 0, 1), worldFromMap(10.0 * i, 5, 100), 5.0f + i, 0.0f,
            0.5f, static_cast<std::uint64_t>(i));
  all.presence[2] = 0.3f;
  all.blendType[2] = library.typeIndex(0, 0, 0);
  all.blendWeight[2] = 0.6f;
  Forest some;
  some.append(all, 2);
  ASSERT_EQ(some.size(), 1u);
  EXPECT_EQ(some.type[0], all.type[2]);
  EXPECT_EQ(some.position[0], all.position[2]);
  EXPECT_EQ(some.yaw[0], all.yaw[2]);
  EXPECT_EQ(some.scaleXZ[0], all.scaleXZ[2]);
  EXPECT_EQ(some.scaleY[0], all.scaleY[2]);
  EXPECT_EQ(some.tint[0], all.tint[2]);
  EXPECT_EQ(some.phase[0], all.phase[2]);
  EXPECT_EQ(some.presence[0], 0.3f);
  EXPECT_EQ(some.blendType[0], all.blendType[2]);
  EXPECT_EQ(some.blendWeight[0], 0.6f);
}

TEST(Forest, AnUnknownSpeciesIsAnInputError) {
  TreeSnapshot snapshot;
  snapshot.speciesNames = {"baobab"};
  snapshot.trees.push_back({.species = 0, .height_m = 3.0f});
  EXPECT_THROW(forestFromSnapshot(snapshot, test::smallLibrary(), "run"), InputError);
}

TEST(Forest, ARunsSnapshotBuiltBatchByBatchIsTheForestOfItsRowsRead) {
  // More rows than a batch of the binary reader (2^20), of every height, light and crown
  // base, so that the batches meet and each draws its own types and leans.
  const TreeLibrary& library = test::shapedLibrary();
  TreeSnapshot snapshot;
  snapshot.year = 1;
  snapshot.speciesNames = {"beech"};
  const std::size_t n = (std::size_t{1} << 20) + 5000;
  for (std::uint64_t id = 1; id <= n; ++id) snapshot.trees.push_back(test::variedTree(id));
  const RunFolder run = test::runHolding("forest_from_run", {&snapshot}, SnapshotFormat::Binary);
  EXPECT_GE(snapshotRowsAtMost(run, 1), n);
  const Forest batched = forestFromRun(run, 1, library);
  test::expectSameForest(batched, forestFromSnapshot(readSnapshot(run, 1), library, "run"));
  EXPECT_EQ(batched.type.capacity(), snapshotRowsAtMost(run, 1));  // reserved once
  EXPECT_GT(typesOf(batched).size(), 1u);
  // Only the rows kept: the same trees as the whole forest's, in order.
  const Forest kept =
      forestFromRun(run, 1, library, [](const TreeRow& t) { return t.id % 7 == 0; });
  Forest expected;
  for (std::size_t i = 6; i < batched.size(); i += 7) expected.append(batched, i);
  test::expectSameForest(kept, expected);
  // And batch by batch, each batch a forest of its own.
  Forest joined;
  int batches = 0;
  forEachForestBatch(run, 1, library, [&](const Forest& batch) {
    ++batches;
    for (std::size_t i = 0; i < batch.size(); ++i) joined.append(batch, i);
  });
  EXPECT_GE(batches, 2);
  test::expectSameForest(joined, batched);
}

TEST(Forest, ARunsCsvSnapshotNamesItsSpeciesAsItsRowsComeAndAnUnknownOneIsAnInputError) {
  const TreeLibrary& library = test::smallLibrary();
  TreeSnapshot snapshot;
  snapshot.year = 1;
  snapshot.speciesNames = {"maple", "beech"};
  for (std::uint64_t id = 1; id <= 40; ++id)
    snapshot.trees.push_back({.id = id,
                              .species = id > 20 ? 1 : 0,
                              .east_m = 3.0 * static_cast<double>(id),
                              .height_m = 0.5f * static_cast<float>(id),
                              .vigor = 0.7f,
                              .variantSeed = static_cast<std::uint32_t>(id)});
  const RunFolder run = test::runHolding("forest_from_run_csv", {&snapshot}, SnapshotFormat::Csv);
  test::expectSameForest(forestFromRun(run, 1, library),
                         forestFromSnapshot(readSnapshot(run, 1), library, "run"));
  snapshot.speciesNames[1] = "baobab";
  const RunFolder foreign =
      test::runHolding("forest_from_run_foreign", {&snapshot}, SnapshotFormat::Csv);
  try {
    forestFromRun(foreign, 1, library);
    ADD_FAILURE() << "a species the library lacks was drawn";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("baobab"), std::string::npos);
  }
}

TEST(Forest, TheDemoPlantingIsDeterministicAndOnTheGround) {
  const Terrain terrain = test::flatTerrain(33, 10.0);
  const Forest a = demoForest(terrain, test::smallLibrary(), 200, 4);
  const Forest b = demoForest(terrain, test::smallLibrary(), 200, 4);
  ASSERT_EQ(a.size(), 200u);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.type, b.type);
  for (const glm::vec3& p : a.position) {
    EXPECT_FLOAT_EQ(p.y, 100.0f);
    EXPECT_GE(p.x, 0.0f);
    EXPECT_LE(p.x, 320.0f);
  }
}

TEST(Forest, ATreeAsBuiltIsNeitherTurnedNorScaledNorTinted) {
  Forest forest;
  forest.addAsBuilt(2, {1.0f, 2.0f, 3.0f});
  ASSERT_EQ(forest.size(), 1u);
  EXPECT_EQ(forest.type[0], 2);
  EXPECT_EQ(forest.position[0], glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(forest.yaw[0], 0.0f);
  EXPECT_EQ(forest.scaleXZ[0], 1.0f);
  EXPECT_EQ(forest.scaleY[0], 1.0f);
  EXPECT_EQ(forest.tint[0], glm::vec3(1.0f));
  EXPECT_EQ(forest.presence[0], 1.0f);
  EXPECT_EQ(forest.blendType[0], -1);
}

}  // namespace
}  // namespace eco
