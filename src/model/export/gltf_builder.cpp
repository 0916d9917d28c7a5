#include "model/export/gltf_builder.hpp"

#include <cctype>
#include <sstream>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace eco {

GltfBuilder::GltfBuilder() {
  model_.asset.version = "2.0";
  model_.asset.generator = "ecoforest";
  model_.buffers.emplace_back();
}

int GltfBuilder::addView(const void* data, std::size_t bytes, int target) {
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

int GltfBuilder::addMaterial(const Material& m) {
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
    material.pbrMetallicRoughness.baseColorTexture.index = addTexture(*m.texture, m.repeat, m.name);
  model_.materials.push_back(material);
  return static_cast<int>(model_.materials.size() - 1);
}

void GltfBuilder::addPrimitive(tinygltf::Mesh& mesh, const MeshPart& part, int material) {
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = material;
  primitive.attributes["POSITION"] =
      addAccessor(part.positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                  TINYGLTF_TARGET_ARRAY_BUFFER, true);
  primitive.attributes["NORMAL"] =
      addAccessor(part.normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                  TINYGLTF_TARGET_ARRAY_BUFFER, false);
  if (!part.uvs.empty())
    primitive.attributes["TEXCOORD_0"] =
        addAccessor(part.uvs, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2,
                    TINYGLTF_TARGET_ARRAY_BUFFER, false);
  primitive.indices =
      addAccessor(part.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                  TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, false);
  mesh.primitives.push_back(primitive);
}

int GltfBuilder::addMesh(tinygltf::Mesh mesh) {
  model_.meshes.push_back(std::move(mesh));
  return static_cast<int>(model_.meshes.size() - 1);
}

int GltfBuilder::addNode(tinygltf::Node node) {
  model_.nodes.push_back(std::move(node));
  return static_cast<int>(model_.nodes.size() - 1);
}

void GltfBuilder::setScene(std::vector<int> roots, tinygltf::Value extras) {
  tinygltf::Scene scene;
  scene.nodes = std::move(roots);
  scene.extras = std::move(extras);
  model_.scenes = {scene};
  model_.defaultScene = 0;
}

void GltfBuilder::useExtension(const std::string& name, bool required) {
  model_.extensionsUsed.push_back(name);
  if (required) model_.extensionsRequired.push_back(name);
}

namespace {

// A file name as a relative URI: characters other than RFC 3986's unreserved ones
// percent-encoded (a space is %20).
std::string uriOf(const std::string& name) {
  std::string uri;
  for (unsigned char c : name) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~')
      uri += static_cast<char>(c);
    else
      uri += fmt::format("%{:02X}", c);
  }
  return uri;
}

}  // namespace

std::filesystem::path GltfBuilder::binaryFileFor(const std::filesystem::path& gltf) {
  return std::filesystem::path(gltf).replace_extension(".bin");
}

void GltfBuilder::write(const std::filesystem::path& file) {
  const bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
  tinygltf::TinyGLTF writer;
  std::ostringstream text;
  if (binary) {
    if (!writer.WriteGltfSceneToStream(&model_, text, /*prettyPrint=*/false, true))
      throw InternalError("tinygltf could not serialise " + file.string());
    AtomicFile out(file);
    out.write(text.view());
    out.commit();
    return;
  }
  // tinygltf's stream writer embeds buffers as base64 (a third larger, slow to parse): the
  // JSON is written without the bytes and its buffer then points at STEM.bin.
  std::vector<unsigned char> bytes = std::move(model_.buffers[0].data);
  model_.buffers[0].data.clear();
  const bool serialised = writer.WriteGltfSceneToStream(&model_, text, true, false);
  model_.buffers[0].data = std::move(bytes);
  if (!serialised) throw InternalError("tinygltf could not serialise " + file.string());
  nlohmann::ordered_json json = nlohmann::ordered_json::parse(text.str());
  const std::filesystem::path bin = binaryFileFor(file);
  json["buffers"][0] = {{"byteLength", model_.buffers[0].data.size()},
                        {"uri", uriOf(bin.filename().string())}};
  AtomicFileSet files;
  files.add(bin).write(model_.buffers[0].data);
  files.add(file).write(json.dump(2) + "\n");
  files.commit();
}

int GltfBuilder::addTexture(const Image& image, bool repeat, const std::string& name) {
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

}  // namespace eco
