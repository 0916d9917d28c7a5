#include "model/mesh/mesh.hpp"

#include <gtest/gtest.h>

namespace eco {

TEST(Mesh, PartsCountTrianglesAndAreFoundByMaterial) {
  TreeMesh mesh;
  MeshPart bark{MaterialKind::Bark, {}, {}, {}, {}};
  std::uint32_t a = bark.addVertex({0, 0, 0}, {0, 0, 1}, {0, 0});
  std::uint32_t b = bark.addVertex({1, 0, 0}, {0, 0, 1}, {1, 0});
  std::uint32_t c = bark.addVertex({0, 1, 0}, {0, 0, 1}, {0, 1});
  bark.addTriangle(a, b, c);
  EXPECT_EQ(c, 2u);
  mesh.parts.push_back(bark);
  EXPECT_EQ(mesh.triangleCount(), 1u);
  ASSERT_NE(mesh.find(MaterialKind::Bark), nullptr);
  EXPECT_EQ(mesh.find(MaterialKind::Leaf), nullptr);
  EXPECT_STREQ(toString(MaterialKind::LeafCluster), "leaf_cluster");
}

}  // namespace eco
