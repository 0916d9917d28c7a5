// VRML97 (.wrl): one Shape with an IndexedFaceSet per material, textures referenced by
// file name. VRML's texture origin is bottom-left, so v is flipped.
#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "model/export/tree_export.hpp"

namespace eco {

void writeVrml(const TreeMesh& mesh, const std::vector<Material>& materials,
               const std::filesystem::path& file) {
  AtomicFileSet files;
  AtomicFile& wrl = files.add(file);
  wrl.write("#VRML V2.0 utf8\n# ecoforest tree\n");
  std::string text;
  for (std::size_t p = 0; p < mesh.parts.size(); ++p) {
    const MeshPart& part = mesh.parts[p];
    const Material& material = materials[p];
    text.clear();
    text += fmt::format(
        "DEF {} Shape {{\n  appearance Appearance {{\n    material Material {{ diffuseColor {:.3f} "
        "{:.3f} {:.3f} }}\n",
        material.name, material.baseColor.r, material.baseColor.g, material.baseColor.b);
    if (material.texture) {
      std::filesystem::path png = textureFileFor(file, material);
      files.add(png).write(encodePng(*material.texture));
      text += fmt::format("    texture ImageTexture {{ url \"{}\" repeatS {} repeatT {} }}\n",
                          png.filename().string(), material.repeat ? "TRUE" : "FALSE",
                          material.repeat ? "TRUE" : "FALSE");
    }
    text += fmt::format(
        "  }}\n  geometry IndexedFaceSet {{\n    solid {}\n    coord Coordinate {{ point [\n",
        material.doubleSided ? "FALSE" : "TRUE");
    for (glm::vec3 v : part.positions)
      text += fmt::format("{:.5f} {:.5f} {:.5f},\n", v.x, v.y, v.z);
    text += "    ] }\n    normal Normal { vector [\n";
    for (glm::vec3 n : part.normals) text += fmt::format("{:.4f} {:.4f} {:.4f},\n", n.x, n.y, n.z);
    text += "    ] }\n    texCoord TextureCoordinate { point [\n";
    for (glm::vec2 t : part.uvs) text += fmt::format("{:.4f} {:.4f},\n", t.x, 1.0f - t.y);
    text += "    ] }\n    coordIndex [\n";
    for (std::size_t i = 0; i < part.indices.size(); i += 3)
      text +=
          fmt::format("{} {} {} -1,\n", part.indices[i], part.indices[i + 1], part.indices[i + 2]);
    text += "    ]\n  }\n}\n";
    wrl.write(text);
  }
  files.commit();
}

}  // namespace eco
