#include <gtest/gtest.h>

#include "model/export/tree_export.hpp"
#include "model/mesh/lod.hpp"
#include "model/strand_model.hpp"
#include "test_support.hpp"

namespace eco {

TEST(ExportVrml, OneShapePerPartAndEveryTriangle) {
  auto dir = test::freshDirectory("vrml");
  Species maple = test::loadNamed("maple");
  TreeMesh mesh = buildLod(buildStrandTree(maple, {}), maple, 1);
  exportTree(mesh, maple, dir / "maple.wrl");
  std::string text = test::readFile(dir / "maple.wrl");
  EXPECT_EQ(text.rfind("#VRML V2.0 utf8\n", 0), 0u);
  std::size_t shapes = 0, faces = 0;
  for (std::size_t at = text.find("Shape {"); at != std::string::npos;
       at = text.find("Shape {", at + 1))
    ++shapes;
  for (std::size_t at = text.find(" -1,"); at != std::string::npos; at = text.find(" -1,", at + 1))
    ++faces;
  EXPECT_EQ(shapes, mesh.parts.size());
  EXPECT_EQ(faces, mesh.triangleCount());
  EXPECT_NE(text.find("url \"maple_bark.png\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "maple_bark.png"));
}

}  // namespace eco
