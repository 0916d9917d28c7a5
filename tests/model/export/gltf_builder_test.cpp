#include "model/export/gltf_builder.hpp"

#include <gtest/gtest.h>

#include "test_files.hpp"

namespace eco {
namespace {

TEST(GltfBuilder, WritesMeshesNodesAndExtensionsThatReadBack) {
  MeshPart part;
  part.addVertex({0, 0, 0}, {0, 1, 0}, {0, 0});
  part.addVertex({1, 0, 0}, {0, 1, 0}, {1, 0});
  part.addVertex({0, 0, -2}, {0, 1, 0}, {0, 1});
  part.addTriangle(0, 1, 2);
  GltfBuilder builder;
  builder.useExtension("EXT_mesh_gpu_instancing", true);
  Material material;
  material.name = "plain";
  tinygltf::Mesh mesh;
  builder.addPrimitive(mesh, part, builder.addMaterial(material));
  tinygltf::Node node;
  node.mesh = builder.addMesh(mesh);
  builder.setScene({builder.addNode(node)});
  const auto file = test::freshDirectory("gltf_builder") / "t.gltf";
  builder.write(file);

  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadASCIIFromFile(&model, &error, &warning, file.string())) << error;
  ASSERT_EQ(model.meshes.size(), 1u);
  const tinygltf::Accessor& positions =
      model.accessors[model.meshes[0].primitives[0].attributes.at("POSITION")];
  EXPECT_EQ(positions.count, 3u);
  EXPECT_EQ(positions.minValues, (std::vector<double>{0, 0, -2}));
  EXPECT_EQ(positions.maxValues, (std::vector<double>{1, 0, 0}));
  EXPECT_EQ(model.accessors[model.meshes[0].primitives[0].indices].count, 3u);
  EXPECT_EQ(model.extensionsUsed, std::vector<std::string>{"EXT_mesh_gpu_instancing"});
  EXPECT_EQ(model.extensionsRequired, std::vector<std::string>{"EXT_mesh_gpu_instancing"});
  EXPECT_EQ(model.materials[0].name, "plain");
}

}  // namespace
}  // namespace eco
