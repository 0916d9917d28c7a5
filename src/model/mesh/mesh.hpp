// Triangle meshes of a tree, one part per material, as parallel arrays ready for GPU buffers
// and exporters. UVs follow glTF's convention: (0, 0) is the top-left of the texture image;
// exporters for formats with a bottom-left origin flip v.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/buffer.hpp"

namespace eco {

enum class MaterialKind { Bark, Leaf, Needle, LeafCluster, Crown };
const char* toString(MaterialKind kind);

struct MeshPart {
  MaterialKind material = MaterialKind::Bark;
  Buffer<glm::vec3> positions;
  Buffer<glm::vec3> normals;
  Buffer<glm::vec2> uvs;
  Buffer<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside

  std::size_t triangleCount() const { return indices.size() / 3; }
  void reserve(std::size_t vertices, std::size_t triangles);
  // Inline: meshing a pine calls these about a million times.
  std::uint32_t addVertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv) {
    positions.push_back(position);
    normals.push_back(normal);
    uvs.push_back(uv);
    return static_cast<std::uint32_t>(positions.size() - 1);
  }
  void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    indices.push_back(a);
    indices.push_back(b);
    indices.push_back(c);
  }
};

struct TreeMesh {
  std::vector<MeshPart> parts;  // non-empty parts only

  std::size_t triangleCount() const;
  const MeshPart* find(MaterialKind material) const;
  // For the ...Into builders: the part of that material, emptied but with its capacity
  // kept (created if missing).
  MeshPart& reusePart(MaterialKind material);
  // Drops the parts that stayed empty.
  void dropEmptyParts();
};

}  // namespace eco
