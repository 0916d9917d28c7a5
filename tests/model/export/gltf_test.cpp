#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "model/export/tree_export.hpp"
#include "model/mesh/lod.hpp"
#include "model/strand_model.hpp"
#include "gltf_files.hpp"
#include "test_support.hpp"

namespace eco {

TEST(ExportGltf, ReadsBackWithTheSameGeometry) {
  auto dir = test::freshDirectory("gltf");
  Species beech = test::loadNamed("beech");
  TreeMesh mesh = buildLod(buildStrandTree(beech, {}), beech, 0);
  for (const char* name : {"beech.glb", "beech.gltf"}) {
    exportTree(mesh, beech, dir / name);
    tinygltf::Model model = test::loadGltf(dir / name);
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.meshes[0].primitives.size(), mesh.parts.size());
    for (std::size_t p = 0; p < mesh.parts.size(); ++p) {
      const tinygltf::Primitive& primitive = model.meshes[0].primitives[p];
      EXPECT_EQ(model.accessors[primitive.attributes.at("POSITION")].count,
                mesh.parts[p].positions.size());
      EXPECT_EQ(model.accessors[primitive.indices].count, mesh.parts[p].indices.size());
      EXPECT_EQ(model.accessors[primitive.attributes.at("POSITION")].minValues.size(), 3u);
    }
    ASSERT_EQ(model.materials.size(), mesh.parts.size());
    const tinygltf::Material& leaf = model.materials[1];
    EXPECT_EQ(leaf.alphaMode, "MASK");
    EXPECT_TRUE(leaf.doubleSided);
    EXPECT_GE(leaf.pbrMetallicRoughness.baseColorTexture.index, 0);
    EXPECT_EQ(model.images.size(), 2u);
  }
}

TEST(ExportGltf, SameSeedSameBytesOtherSeedOtherBytes) {
  auto dir = test::freshDirectory("gltf_determinism");
  Species maple = test::loadNamed("maple");
  auto write = [&](std::uint64_t seed, const char* folder) {
    std::filesystem::create_directories(dir / folder);
    auto file = dir / folder / "maple.glb";  // the file name is the mesh's name
    exportTree(buildLod(buildStrandTree(maple, {.seed = seed}), maple, 0), maple, file);
    return test::readFile(file);
  };
  std::string a = write(3, "a"), b = write(3, "b"), c = write(4, "c");
  EXPECT_TRUE(a == b) << "same seed, different bytes";
  EXPECT_FALSE(a == c) << "different seeds, same bytes";
}

}  // namespace eco
