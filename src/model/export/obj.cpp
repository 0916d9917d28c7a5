// Wavefront OBJ with an MTL library and PNG textures. OBJ's texture origin is the
// bottom-left corner, so v is flipped.
#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "model/export/tree_export.hpp"

namespace eco {

void writeObj(const TreeMesh& mesh, const std::vector<Material>& materials,
              const std::filesystem::path& file) {
  AtomicFileSet files;
  std::filesystem::path mtlPath = file;
  mtlPath.replace_extension(".mtl");
  AtomicFile& obj = files.add(file);
  AtomicFile& mtl = files.add(mtlPath);

  obj.write(fmt::format("# ecoforest tree\nmtllib {}\n", mtlPath.filename().string()));
  std::string text;
  std::size_t base = 1;  // OBJ indices start at 1 and run across the whole file
  for (std::size_t p = 0; p < mesh.parts.size(); ++p) {
    const MeshPart& part = mesh.parts[p];
    const Material& material = materials[p];
    text.clear();
    text += fmt::format("o {}\nusemtl {}\n", material.name, material.name);
    for (glm::vec3 v : part.positions)
      text += fmt::format("v {:.5f} {:.5f} {:.5f}\n", v.x, v.y, v.z);
    for (glm::vec3 n : part.normals)
      text += fmt::format("vn {:.4f} {:.4f} {:.4f}\n", n.x, n.y, n.z);
    for (glm::vec2 t : part.uvs) text += fmt::format("vt {:.4f} {:.4f}\n", t.x, 1.0f - t.y);
    for (std::size_t i = 0; i < part.indices.size(); i += 3) {
      std::size_t a = part.indices[i] + base, b = part.indices[i + 1] + base,
                  c = part.indices[i + 2] + base;
      text += fmt::format("f {0}/{0}/{0} {1}/{1}/{1} {2}/{2}/{2}\n", a, b, c);
    }
    obj.write(text);
    base += part.positions.size();

    mtl.write(fmt::format("newmtl {}\nKd {:.4f} {:.4f} {:.4f}\nKs 0 0 0\nillum 1\n", material.name,
                          material.baseColor.r, material.baseColor.g, material.baseColor.b));
    if (material.texture) {
      std::filesystem::path png = textureFileFor(file, material);
      mtl.write(fmt::format("map_Kd {}\n", png.filename().string()));
      if (material.alphaMask) mtl.write(fmt::format("map_d {}\n", png.filename().string()));
      files.add(png).write(encodePng(*material.texture));
    }
    mtl.write("\n");
  }
  files.commit();
}

}  // namespace eco
