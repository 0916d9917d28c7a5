#include "model/species_writer.hpp"

#include <cstring>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "model/mesh/lod.hpp"
#include "model/tree_generator.hpp"
#include "test_support.hpp"

namespace eco {
namespace {

template <typename T>
bool sameBytes(const Buffer<T>& a, const Buffer<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

bool sameMesh(const TreeMesh& a, const TreeMesh& b) {
  if (a.parts.size() != b.parts.size()) return false;
  for (std::size_t i = 0; i < a.parts.size(); ++i)
    if (!sameBytes(a.parts[i].positions, b.parts[i].positions) ||
        !sameBytes(a.parts[i].normals, b.parts[i].normals) ||
        !sameBytes(a.parts[i].indices, b.parts[i].indices))
      return false;
  return true;
}

}  // namespace

class SpeciesWriterRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(SpeciesWriterRoundTrip, SavedSpeciesBuildsTheSameTreeByteForByte) {
  const Species original = test::loadNamed(GetParam());
  const std::filesystem::path saved = test::writeTemporary("saved", "");
  saveSpecies(original, saved);
  const Species loaded = loadSpecies(saved);
  for (std::uint64_t seed : {1u, 7u}) {
    TreeBuildOptions options;
    options.seed = seed;
    options.age = seed == 1 ? 1.0 : 0.6;
    const TreeSkeleton a = buildTree(original, options), b = buildTree(loaded, options);
    ASSERT_EQ(a.segments.size(), b.segments.size());
    EXPECT_TRUE(sameMesh(buildLod(a, original, 0), buildLod(b, loaded, 0)));
  }
  // Saving what was loaded gives the same text again (apart from the file it names).
  const std::filesystem::path again = test::writeTemporary("again", "");
  Species reloaded = loaded;
  reloaded.file = original.file;
  saveSpecies(reloaded, again);
  EXPECT_EQ(test::readFile(again), test::readFile(saved));
}

INSTANTIATE_TEST_SUITE_P(ShippedStrandSpecies, SpeciesWriterRoundTrip,
                         ::testing::Values("beech", "pine", "maple", "shrub"));

TEST(SpeciesWriter, NumbersReadBackExactly) {
  Species beech = test::loadNamed("beech");
  beech.strand.kc = 0.1 + 0.2;  // 0.30000000000000004: needs all 17 digits
  beech.strand.graphs.alphaG = Polyline({{0.0, 1.0 / 3.0}, {7.123456789012345, 45.0}});
  beech.wind.direction = {0.1, 0.98, -1e-7};
  const std::filesystem::path saved = test::writeTemporary("exact", "");
  saveSpecies(beech, saved);
  const Species loaded = loadSpecies(saved);
  EXPECT_EQ(loaded.strand.kc, 0.1 + 0.2);
  EXPECT_EQ(loaded.strand.graphs.alphaG.points()[0].y, 1.0 / 3.0);
  EXPECT_EQ(loaded.strand.graphs.alphaG.points()[1].x, 7.123456789012345);
  EXPECT_EQ(loaded.wind.direction, beech.wind.direction);
}

TEST(SpeciesWriter, KeepsTheEcologyTablesWithTheirComments) {
  const Species beech = test::loadNamed("beech");
  const std::string ecology = ecologyTablesOf(beech.file);
  EXPECT_EQ(ecology.rfind("# Ecology for the ecosystem simulation", 0), 0u) << ecology;
  EXPECT_NE(ecology.find("[ecology]\n"), std::string::npos);
  EXPECT_NE(ecology.find("[ecology.tolerance]"), std::string::npos);
  EXPECT_NE(ecology.find("[ecology.life]"), std::string::npos);
  EXPECT_EQ(ecology.find("[strand"), std::string::npos);
  EXPECT_EQ(ecology.find("[appearance]"), std::string::npos);
  // Every line of the original from the ecology's comment on is kept, in order.
  const std::string original = test::readFile(beech.file);
  EXPECT_EQ(original.substr(original.find("# Ecology for the ecosystem")), ecology);
}

TEST(SpeciesWriter, TablesAfterTheEcologyAndTheirCommentsStayOut) {
  const auto file = test::writeTemporary("mixed", R"(name = "x"
# about the ecology
[ecology]
a = 1
# about the look
[appearance]
b = 2
[ecology.life]
c = 3
)");
  EXPECT_EQ(ecologyTablesOf(file),
            "# about the ecology\n[ecology]\na = 1\n[ecology.life]\nc = 3\n");
}

TEST(SpeciesWriter, RefusesAnLSystemSpecies) {
  const Species birch = test::loadNamed("birch");
  EXPECT_THROW(saveSpecies(birch, test::writeTemporary("birch", "")), InputError);
}

}  // namespace eco
