// Writing a tree mesh to files other tools read: OBJ (+MTL), glTF 2.0 (.gltf/.glb),
// POV-Ray scenes and VRML97 -- the formats of the Green paper plus today's standard.
// Every writer is all-or-nothing (core/atomic_file.hpp). Textures go beside the file as
// STEM_MATERIAL.png, except in glTF, which embeds them.
#pragma once

#include <filesystem>
#include <vector>

#include "model/mesh/mesh.hpp"
#include "model/mesh/textures.hpp"

namespace eco {

// One material per part of the mesh, in the same order.
std::vector<Material> materialsFor(const TreeMesh& mesh, const Species& species);

void writeObj(const TreeMesh& mesh, const std::vector<Material>& materials,
              const std::filesystem::path& file);
void writeGltf(const TreeMesh& mesh, const std::vector<Material>& materials,
               const std::filesystem::path& file);
void writePov(const TreeMesh& mesh, const std::vector<Material>& materials,
              const std::filesystem::path& file);
void writeVrml(const TreeMesh& mesh, const std::vector<Material>& materials,
               const std::filesystem::path& file);

// Chooses the writer by extension (.obj .gltf .glb .pov .wrl); another extension is an
// InputError naming the file.
void exportTree(const TreeMesh& mesh, const Species& species, const std::filesystem::path& file);
// The checks exportTree would fail on (format, output folder), for commands to run before
// any slow work.
void checkTreeExportPath(const std::filesystem::path& file);

// STEM_MATERIAL.png beside `file`, for formats that reference textures by name.
std::filesystem::path textureFileFor(const std::filesystem::path& file, const Material& material);

// Axis-aligned bounds of all parts; used to frame cameras.
struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};
Bounds boundsOf(const TreeMesh& mesh);

}  // namespace eco
