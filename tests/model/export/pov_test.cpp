#include <cstdlib>

#include <gtest/gtest.h>

#include "model/export/tree_export.hpp"
#include "model/mesh/lod.hpp"
#include "model/strand_model.hpp"
#include "test_support.hpp"

namespace eco {

TEST(ExportPov, SceneHasCameraLightAndEveryPart) {
  auto dir = test::freshDirectory("pov");
  Species shrub = test::loadNamed("shrub");
  TreeMesh mesh = buildLod(buildStrandTree(shrub, {}), shrub, 1);
  exportTree(mesh, shrub, dir / "hazel.pov");
  std::string scene = test::readFile(dir / "hazel.pov");
  EXPECT_NE(scene.find("#version 3.7;"), std::string::npos);
  EXPECT_NE(scene.find("camera {"), std::string::npos);
  EXPECT_NE(scene.find("light_source {"), std::string::npos);
  std::size_t meshes = 0;
  for (std::size_t at = scene.find("mesh2 {"); at != std::string::npos;
       at = scene.find("mesh2 {", at + 1))
    ++meshes;
  EXPECT_EQ(meshes, mesh.parts.size());
  EXPECT_NE(scene.find("face_indices { " + std::to_string(mesh.parts[0].triangleCount())),
            std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "hazel_leaf.png"));
}

TEST(ExportPov, PovRayRendersIt) {
  if (std::system("command -v povray >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "povray is not installed";
  auto dir = test::freshDirectory("pov_render");
  Species shrub = test::loadNamed("shrub");
  exportTree(buildLod(buildStrandTree(shrub, {}), shrub, 0), shrub, dir / "hazel.pov");
  std::string command =
      "cd " + dir.string() + " && povray +Ihazel.pov +Ohazel.png +W64 +H64 -D -V >povray.log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << test::readFile(dir / "povray.log");
  EXPECT_GT(std::filesystem::file_size(dir / "hazel.png"), 100u);
}

}  // namespace eco
