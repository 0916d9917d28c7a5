#include "model/mesh/mesh.hpp"

namespace eco {

const char* toString(MaterialKind kind) {
  switch (kind) {
    case MaterialKind::Bark:
      return "bark";
    case MaterialKind::Leaf:
      return "leaf";
    case MaterialKind::Needle:
      return "needle";
    case MaterialKind::LeafCluster:
      return "leaf_cluster";
    case MaterialKind::Crown:
      return "crown";
  }
  return "?";
}

void MeshPart::reserve(std::size_t vertices, std::size_t triangles) {
  positions.reserve(positions.size() + vertices);
  normals.reserve(normals.size() + vertices);
  uvs.reserve(uvs.size() + vertices);
  indices.reserve(indices.size() + 3 * triangles);
}

std::size_t TreeMesh::triangleCount() const {
  std::size_t count = 0;
  for (const MeshPart& part : parts) count += part.triangleCount();
  return count;
}

MeshPart& TreeMesh::reusePart(MaterialKind material) {
  for (MeshPart& part : parts)
    if (part.material == material) {
      part.positions.clear();
      part.normals.clear();
      part.uvs.clear();
      part.indices.clear();
      return part;
    }
  parts.push_back(MeshPart{material, {}, {}, {}, {}});
  return parts.back();
}

void TreeMesh::dropEmptyParts() {
  std::erase_if(parts, [](const MeshPart& part) { return part.indices.empty(); });
}

const MeshPart* TreeMesh::find(MaterialKind material) const {
  for (const MeshPart& part : parts)
    if (part.material == material) return &part;
  return nullptr;
}

}  // namespace eco
