#include "model/export/gltf_builder.hpp"

#include <cctype>
#include <cstdint>
#include <iterator>
#include <limits>
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

int GltfBuilder::addRootNodesJson(std::string_view objects, std::size_t count) {
  if (count == 0) return -1;
  const int first = static_cast<int>(model_.nodes.size() + rawNodeCount_);
  if (!rawNodes_.empty()) rawNodes_ += ',';
  rawNodes_ += objects;
  rawNodeCount_ += count;
  return first;
}

void GltfBuilder::write(const std::filesystem::path& file) {
  const bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
  // The JSON without the buffer's bytes (tinygltf's stream writer would embed them as
  // base64) and without the raw nodes: both are put in place below.
  std::vector<unsigned char> bytes = std::move(model_.buffers[0].data);
  model_.buffers[0].data.clear();
  std::ostringstream text;
  const bool serialised = tinygltf::TinyGLTF().WriteGltfSceneToStream(&model_, text, false, false);
  model_.buffers[0].data = std::move(bytes);
  if (!serialised) throw InternalError("tinygltf could not serialise " + file.string());
  const std::vector<unsigned char>& data = model_.buffers[0].data;
  nlohmann::ordered_json json = nlohmann::ordered_json::parse(text.str());
  const std::filesystem::path bin = binaryFileFor(file);
  if (binary)
    json["buffers"][0] = {{"byteLength", data.size()}};
  else
    json["buffers"][0] = {{"byteLength", data.size()}, {"uri", uriOf(bin.filename().string())}};
  // The raw nodes and their root indices go where two markers stand in the JSON text.
  constexpr std::string_view kNodes = "\"@ecoforest:nodes@\"", kRoots = "\"@ecoforest:roots@\"";
  std::string roots;
  if (rawNodeCount_ > 0) {
    json["nodes"].push_back(kNodes.substr(1, kNodes.size() - 2));
    json["scenes"][0]["nodes"].push_back(kRoots.substr(1, kRoots.size() - 2));
    roots.reserve(rawNodeCount_ * 8);
    for (std::size_t i = 0; i < rawNodeCount_; ++i)
      fmt::format_to(std::back_inserter(roots), "{}{}", i ? "," : "", model_.nodes.size() + i);
  }
  const std::string head = json.dump(binary ? -1 : 2);
  std::vector<std::string_view> pieces;
  std::size_t from = 0;
  for (auto [marker, replacement] : {std::pair{kNodes, std::string_view(rawNodes_)},
                                     std::pair{kRoots, std::string_view(roots)}}) {
    if (rawNodeCount_ == 0) break;
    const std::size_t at = head.find(marker, from);
    if (at == std::string::npos) throw InternalError("glTF node markers out of order");
    pieces.push_back(std::string_view(head).substr(from, at - from));
    pieces.push_back(replacement);
    from = at + marker.size();
  }
  pieces.push_back(std::string_view(head).substr(from));
  std::size_t jsonBytes = 0;
  for (std::string_view piece : pieces) jsonBytes += piece.size();

  if (!binary) {
    AtomicFileSet files;
    files.add(bin).write(data);
    AtomicFile& out = files.add(file);
    for (std::string_view piece : pieces) out.write(piece);
    out.write("\n");
    files.commit();
    return;
  }
  // The GLB container: a header, the JSON chunk padded with spaces, the binary chunk padded
  // with zeros, each chunk 4-byte aligned (glTF 2.0, section 4.4).
  auto padded = [](std::size_t n) { return (n + 3) & ~std::size_t{3}; };
  const std::size_t jsonChunk = padded(jsonBytes), binChunk = padded(data.size());
  const std::size_t total = 12 + 8 + jsonChunk + (data.empty() ? 0 : 8 + binChunk);
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw InputError({file.string(), 0, ""},
                     "the forest is larger than a .glb holds (4 GiB): export fewer trees "
                     "(--min-height) or use --instancing gpu");
  auto word = [](std::uint32_t v) {
    return std::string{static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff),
                       static_cast<char>((v >> 16) & 0xff), static_cast<char>(v >> 24)};
  };
  AtomicFile out(file);
  out.write(word(0x46546C67u) + word(2) + word(static_cast<std::uint32_t>(total)));
  out.write(word(static_cast<std::uint32_t>(jsonChunk)) + word(0x4E4F534Au));
  for (std::string_view piece : pieces) out.write(piece);
  out.write(std::string(jsonChunk - jsonBytes, ' '));
  if (!data.empty()) {
    out.write(word(static_cast<std::uint32_t>(binChunk)) + word(0x004E4942u));
    out.write(data);
    out.write(std::string(binChunk - data.size(), '\0'));
  }
  out.commit();
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
