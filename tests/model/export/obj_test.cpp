#include <sstream>

#include <gtest/gtest.h>

#include "model/export/tree_export.hpp"
#include "model/mesh/lod.hpp"
#include "model/strand_model.hpp"
#include "test_support.hpp"

namespace eco {

TEST(ExportObj, CountsAndReferencesMatchTheMesh) {
  auto dir = test::freshDirectory("obj");
  Species shrub = test::loadNamed("shrub");
  TreeMesh mesh = buildLod(buildStrandTree(shrub, {}), shrub, 0);
  exportTree(mesh, shrub, dir / "hazel.obj");
  std::istringstream obj(test::readFile(dir / "hazel.obj"));
  std::size_t vertices = 0, faces = 0, maxIndex = 0;
  std::string line;
  while (std::getline(obj, line)) {
    if (line.rfind("v ", 0) == 0) ++vertices;
    if (line.rfind("f ", 0) == 0) {
      ++faces;
      std::istringstream f(line.substr(2));
      std::string corner;
      while (f >> corner) maxIndex = std::max<std::size_t>(maxIndex, std::stoul(corner));
    }
  }
  std::size_t meshVertices = 0;
  for (const MeshPart& p : mesh.parts) meshVertices += p.positions.size();
  EXPECT_EQ(vertices, meshVertices);
  EXPECT_EQ(faces, mesh.triangleCount());
  EXPECT_EQ(maxIndex, meshVertices);  // 1-based and within range
  std::string mtl = test::readFile(dir / "hazel.mtl");
  EXPECT_NE(mtl.find("newmtl shrub_bark"), std::string::npos);
  EXPECT_NE(mtl.find("map_d hazel_leaf.png"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "hazel_bark.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "hazel_leaf.png"));
}

}  // namespace eco
