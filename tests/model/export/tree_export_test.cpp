#include "model/export/tree_export.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "model/mesh/lod.hpp"
#include "model/strand_model.hpp"
#include "test_support.hpp"

namespace eco {

TEST(TreeExport, UnknownExtensionIsAnInputErrorAndWritesNothing) {
  auto dir = test::freshDirectory("export_ext");
  Species shrub = test::loadNamed("shrub");
  TreeMesh mesh = buildLod(buildStrandTree(shrub, {}), shrub, 2);
  try {
    exportTree(mesh, shrub, dir / "tree.fbx");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("unknown output format '.fbx'"), std::string::npos);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(TreeExport, UnwritableFolderLeavesNothing) {
  Species shrub = test::loadNamed("shrub");
  TreeMesh mesh = buildLod(buildStrandTree(shrub, {}), shrub, 2);
  EXPECT_THROW(exportTree(mesh, shrub, "/nonexistent/dir/tree.obj"), InputError);
}

TEST(TreeExport, BoundsAndTextureNames) {
  TreeMesh mesh;
  MeshPart part{MaterialKind::Leaf, {{-1, 0, 2}, {3, 4, -5}}, {}, {}, {}};
  mesh.parts.push_back(part);
  Bounds b = boundsOf(mesh);
  EXPECT_EQ(b.min, glm::vec3(-1, 0, -5));
  EXPECT_EQ(b.max, glm::vec3(3, 4, 2));
  Material m;
  m.kind = MaterialKind::Leaf;
  EXPECT_EQ(textureFileFor("/tmp/x/tree.obj", m), std::filesystem::path("/tmp/x/tree_leaf.png"));
}

}  // namespace eco
