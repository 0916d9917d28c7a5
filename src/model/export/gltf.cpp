// glTF 2.0 through tinygltf: one mesh with a primitive per material, PBR materials with
// embedded PNG textures (alpha mask for leaves), one binary buffer. .glb writes the binary
// container, .gltf a JSON file with the buffer beside it as STEM.bin.
#include "model/export/gltf_builder.hpp"
#include "model/export/tree_export.hpp"

namespace eco {

void writeGltf(const TreeMesh& mesh, const std::vector<Material>& materials,
               const std::filesystem::path& file) {
  GltfBuilder builder;
  tinygltf::Mesh gltfMesh;
  gltfMesh.name = file.stem().string();
  for (std::size_t p = 0; p < mesh.parts.size(); ++p)
    builder.addPrimitive(gltfMesh, mesh.parts[p], builder.addMaterial(materials[p]));
  tinygltf::Node node;
  node.name = gltfMesh.name;
  node.mesh = builder.addMesh(std::move(gltfMesh));
  builder.setScene({builder.addNode(std::move(node))});
  builder.write(file);
}

}  // namespace eco
