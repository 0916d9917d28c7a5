// Triangle meshes of a tree, one part per material, as parallel arrays ready for GPU buffers
// and exporters. UVs follow glTF's convention: (0, 0) is the top-left of the texture image;
// exporters for formats with a bottom-left origin flip v.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace eco {

enum class MaterialKind { Bark, Leaf, Needle, LeafCluster, Crown };
const char* toString(MaterialKind kind);

struct MeshPart {
  MaterialKind material = MaterialKind::Bark;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside

  std::size_t triangleCount() const { return indices.size() / 3; }
  std::uint32_t addVertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv);
  void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
};

struct TreeMesh {
  std::vector<MeshPart> parts;  // non-empty parts only

  std::size_t triangleCount() const;
  const MeshPart* find(MaterialKind material) const;
};

}  // namespace eco
