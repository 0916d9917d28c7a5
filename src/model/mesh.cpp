#include "model/mesh.hpp"

namespace eco {

const char* toString(MaterialKind kind) {
  switch (kind) {
    case MaterialKind::Bark: return "bark";
    case MaterialKind::Leaf: return "leaf";
    case MaterialKind::Needle: return "needle";
    case MaterialKind::LeafCluster: return "leaf_cluster";
    case MaterialKind::Crown: return "crown";
  }
  return "?";
}

std::uint32_t MeshPart::addVertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv) {
  positions.push_back(position);
  normals.push_back(normal);
  uvs.push_back(uv);
  return static_cast<std::uint32_t>(positions.size() - 1);
}

void MeshPart::addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  indices.insert(indices.end(), {a, b, c});
}

std::size_t TreeMesh::triangleCount() const {
  std::size_t count = 0;
  for (const MeshPart& part : parts) count += part.triangleCount();
  return count;
}

const MeshPart* TreeMesh::find(MaterialKind material) const {
  for (const MeshPart& part : parts)
    if (part.material == material) return &part;
  return nullptr;
}

}  // namespace eco
