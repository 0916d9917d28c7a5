// glTF 2.0 through tinygltf: one mesh with a primitive per material, PBR materials with
// embedded PNG textures (alpha mask for leaves), one binary buffer. .glb writes the binary
// container, .gltf a JSON file with the buffer embedded as a data URI.
#include <cstring>
#include <limits>
#include <type_traits>

#include <glm/common.hpp>
#include <sstream>

#include <tiny_gltf.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "model/tree_export.hpp"

namespace eco {
namespace {

class GltfBuilder {
 public:
  GltfBuilder() {
    model_.asset.version = "2.0";
    model_.asset.generator = "ecoforest";
    model_.buffers.emplace_back();
  }

  // Appends bytes as a buffer view (4-byte aligned) and returns its index.
  int addView(const void* data, std::size_t bytes, int target) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    while (buffer.size() % 4 != 0) buffer.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), begin, begin + bytes);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size() - 1);
  }

  template <typename T>
  int addAccessor(const Buffer<T>& values, int componentType, int type, int target,
                  bool withBounds) {
    tinygltf::Accessor accessor;
    accessor.bufferView = addView(values.data(), values.size() * sizeof(T), target);
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = values.size();
    if constexpr (std::is_same_v<T, glm::vec3>) {
      if (withBounds) {  // glTF requires min and max for POSITION
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

  int addMaterial(const Material& m) {
    tinygltf::Material material;
    material.name = m.name;
    material.pbrMetallicRoughness.baseColorFactor = {m.baseColor.r, m.baseColor.g, m.baseColor.b,
                                                     m.baseColor.a};
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = m.roughness;
    material.doubleSided = m.doubleSided;
    if (m.alphaMask) {
      material.alphaMode = "MASK";
      material.alphaCutoff = 0.5;
    }
    if (m.texture)
      material.pbrMetallicRoughness.baseColorTexture.index =
          addTexture(*m.texture, m.repeat, m.name);
    model_.materials.push_back(material);
    return static_cast<int>(model_.materials.size() - 1);
  }

  void addPrimitive(const MeshPart& part, int material) {
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = material;
    primitive.attributes["POSITION"] =
        addAccessor(part.positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                    TINYGLTF_TARGET_ARRAY_BUFFER, true);
    primitive.attributes["NORMAL"] =
        addAccessor(part.normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                    TINYGLTF_TARGET_ARRAY_BUFFER, false);
    primitive.attributes["TEXCOORD_0"] =
        addAccessor(part.uvs, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2,
                    TINYGLTF_TARGET_ARRAY_BUFFER, false);
    primitive.indices =
        addAccessor(part.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                    TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, false);
    mesh_.primitives.push_back(primitive);
  }

  tinygltf::Model& finish(const std::string& name) {
    mesh_.name = name;
    model_.meshes.push_back(mesh_);
    tinygltf::Node node;
    node.name = name;
    node.mesh = 0;
    model_.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    model_.scenes.push_back(scene);
    model_.defaultScene = 0;
    return model_;
  }

 private:
  int addTexture(const Image& image, bool repeat, const std::string& name) {
    std::vector<std::uint8_t> png = encodePng(image);
    tinygltf::Image gltfImage;
    gltfImage.name = name;
    gltfImage.mimeType = "image/png";
    gltfImage.bufferView = addView(png.data(), png.size(), 0);
    model_.images.push_back(gltfImage);
    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = repeat ? TINYGLTF_TEXTURE_WRAP_REPEAT : TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    sampler.wrapT = sampler.wrapS;
    model_.samplers.push_back(sampler);
    tinygltf::Texture texture;
    texture.source = static_cast<int>(model_.images.size() - 1);
    texture.sampler = static_cast<int>(model_.samplers.size() - 1);
    model_.textures.push_back(texture);
    return static_cast<int>(model_.textures.size() - 1);
  }

  tinygltf::Model model_;
  tinygltf::Mesh mesh_;
};

}  // namespace

void writeGltf(const TreeMesh& mesh, const std::vector<Material>& materials,
               const std::filesystem::path& file) {
  GltfBuilder builder;
  for (std::size_t p = 0; p < mesh.parts.size(); ++p)
    builder.addPrimitive(mesh.parts[p], builder.addMaterial(materials[p]));
  tinygltf::Model& model = builder.finish(file.stem().string());

  const bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
  std::ostringstream text;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, text, /*prettyPrint=*/!binary, binary))
    throw InternalError("tinygltf could not serialise " + file.string());
  AtomicFile out(file);
  out.write(text.view());
  out.commit();
}

}  // namespace eco
