#include "model/export/tree_export.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

#include <glm/common.hpp>

#include "core/error.hpp"

namespace eco {

std::vector<Material> materialsFor(const TreeMesh& mesh, const Species& species) {
  std::vector<Material> materials;
  for (const MeshPart& part : mesh.parts) materials.push_back(makeMaterial(part.material, species));
  return materials;
}

std::filesystem::path textureFileFor(const std::filesystem::path& file, const Material& material) {
  std::filesystem::path texture = file;
  texture.replace_filename(file.stem().string() + "_" + toString(material.kind) + ".png");
  return texture;
}

Bounds boundsOf(const TreeMesh& mesh) {
  Bounds b{glm::vec3(std::numeric_limits<float>::max()),
           glm::vec3(std::numeric_limits<float>::lowest())};
  for (const MeshPart& part : mesh.parts)
    for (glm::vec3 p : part.positions) {
      b.min = glm::min(b.min, p);
      b.max = glm::max(b.max, p);
    }
  if (b.min.x > b.max.x) b = Bounds{};
  return b;
}

namespace {

using TreeWriter = void (*)(const TreeMesh&, const std::vector<Material>&,
                            const std::filesystem::path&);

TreeWriter writerFor(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return writeObj;
  if (extension == ".gltf" || extension == ".glb") return writeGltf;
  if (extension == ".pov") return writePov;
  if (extension == ".wrl") return writeVrml;
  throw InputError({file.string(), 0, ""}, "unknown output format '" + extension +
                                               "' (expected .obj, .gltf, .glb, .pov or .wrl)");
}

}  // namespace

void checkTreeExportPath(const std::filesystem::path& file) {
  writerFor(file);
  const std::filesystem::path folder = file.parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder))
    throw InputError({file.string(), 0, ""}, "the output folder does not exist");
}

void exportTree(const TreeMesh& mesh, const Species& species, const std::filesystem::path& file) {
  writerFor(file)(mesh, materialsFor(mesh, species), file);
}

}  // namespace eco
