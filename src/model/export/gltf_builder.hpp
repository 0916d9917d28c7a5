// Building glTF 2.0 files through tinygltf, shared by the single-tree exporter and the
// whole-forest export: one binary buffer, accessors over it, PBR materials with embedded PNG
// textures, meshes with one primitive per material part. write() chooses the container by
// extension: .glb binary, .gltf JSON with the buffer beside it as STEM.bin; atomically.
// tinygltf serialises the JSON; the GLB container and the buffer's place are written here.
#pragma once

#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <tiny_gltf.h>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "model/mesh/mesh.hpp"
#include "model/mesh/textures.hpp"

namespace eco {

class GltfBuilder {
 public:
  GltfBuilder();

  // Appends bytes as a buffer view (4-byte aligned) and returns its index.
  int addView(const void* data, std::size_t bytes, int target);

  // An accessor over `values` (a contiguous container); vec3 accessors get min and max when
  // `withBounds` (glTF requires them for POSITION).
  template <typename Container>
  int addAccessor(const Container& values, int componentType, int type, int target,
                  bool withBounds) {
    using T = typename Container::value_type;
    tinygltf::Accessor accessor;
    accessor.bufferView = addView(values.data(), values.size() * sizeof(T), target);
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = values.size();
    if constexpr (std::is_same_v<T, glm::vec3>) {
      if (withBounds) {
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (const glm::vec3& v : values) {
          lo = glm::min(lo, v);
          hi = glm::max(hi, v);
        }
        accessor.minValues = {lo.x, lo.y, lo.z};
        accessor.maxValues = {hi.x, hi.y, hi.z};
      }
    }
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size() - 1);
  }

  int addMaterial(const Material& material);
  // A primitive of `part` with `material`, appended to `mesh`.
  void addPrimitive(tinygltf::Mesh& mesh, const MeshPart& part, int material);
  int addMesh(tinygltf::Mesh mesh);
  int addNode(tinygltf::Node node);
  // Nodes already written as JSON objects, comma-separated, for scenes of millions of nodes
  // (tinygltf's objects cost kilobytes each while writing): they follow every node added
  // with addNode, so they are added last, and they are roots of the scene. Returns the
  // index the first of them will have.
  int addRootNodesJson(std::string_view objects, std::size_t count);
  // The scene of the given root nodes (the default scene), with optional extras.
  void setScene(std::vector<int> roots, tinygltf::Value extras = {});
  void useExtension(const std::string& name, bool required);

  tinygltf::Model& model() { return model_; }
  void write(const std::filesystem::path& file);
  // Where a .gltf file's buffer goes.
  static std::filesystem::path binaryFileFor(const std::filesystem::path& gltf);

 private:
  int addTexture(const Image& image, bool repeat, const std::string& name);

  tinygltf::Model model_;
  std::string rawNodes_;  // addRootNodesJson's, comma-separated
  std::size_t rawNodeCount_ = 0;
};

}  // namespace eco
