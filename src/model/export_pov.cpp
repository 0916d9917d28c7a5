// A POV-Ray 3.7 scene: the tree as mesh2 objects with image-mapped textures, a camera
// framing the tree, a sun and a sky, on a ground plane. POV-Ray is left-handed (y up, z
// away from the viewer), so z is mirrored; its image origin is bottom-left, so v is flipped.
#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "model/tree_export.hpp"

namespace eco {

void writePov(const TreeMesh& mesh, const std::vector<Material>& materials, const std::filesystem::path& file) {
  AtomicFileSet files;
  AtomicFile& pov = files.add(file);
  Bounds b = boundsOf(mesh);
  glm::vec3 center = 0.5f * (b.min + b.max);
  float height = b.max.y - b.min.y;
  float width = std::max(b.max.x - b.min.x, b.max.z - b.min.z);
  float distance = 1.3f * std::max(height, width) + 1.0f;

  pov.write(fmt::format(
      "// ecoforest tree; render with: povray +I{0} +W800 +H800 +A\n"
      "#version 3.7;\n"
      "global_settings {{ assumed_gamma 1.0 }}\n"
      "camera {{ location <{1:.3f}, {2:.3f}, {3:.3f}> look_at <{4:.3f}, {5:.3f}, {6:.3f}> angle 50 }}\n"
      "light_source {{ <{7:.1f}, {8:.1f}, {9:.1f}> color rgb <1.0, 0.97, 0.9> }}\n"
      "light_source {{ <{10:.1f}, {8:.1f}, {11:.1f}> color rgb 0.35 shadowless }}\n"
      "sky_sphere {{ pigment {{ gradient y color_map {{ [0 color rgb <0.75, 0.85, 1.0>] [1 color rgb <0.3, 0.5, 0.9>] }} }} }}\n"
      "plane {{ y, 0 pigment {{ color rgb <0.35, 0.42, 0.25> }} }}\n",
      file.filename().string(), center.x + 0.3f * distance, center.y + 0.15f * height, -(center.z - distance),
      center.x, center.y, -center.z, center.x + 2.0f * distance, center.y + 4.0f * distance,
      -(center.z - 3.0f * distance), center.x - 3.0f * distance, -(center.z + distance)));

  std::string text;
  for (std::size_t p = 0; p < mesh.parts.size(); ++p) {
    const MeshPart& part = mesh.parts[p];
    const Material& material = materials[p];
    text.clear();
    text += fmt::format("// {}\nmesh2 {{\n  vertex_vectors {{ {}", material.name, part.positions.size());
    for (glm::vec3 v : part.positions) text += fmt::format(",\n<{:.5f},{:.5f},{:.5f}>", v.x, v.y, -v.z);
    text += fmt::format("\n  }}\n  normal_vectors {{ {}", part.normals.size());
    for (glm::vec3 n : part.normals) text += fmt::format(",\n<{:.4f},{:.4f},{:.4f}>", n.x, n.y, -n.z);
    text += fmt::format("\n  }}\n  uv_vectors {{ {}", part.uvs.size());
    for (glm::vec2 t : part.uvs) text += fmt::format(",\n<{:.4f},{:.4f}>", t.x, 1.0f - t.y);
    text += fmt::format("\n  }}\n  face_indices {{ {}", part.triangleCount());
    for (std::size_t i = 0; i < part.indices.size(); i += 3)
      text += fmt::format(",\n<{},{},{}>", part.indices[i], part.indices[i + 1], part.indices[i + 2]);
    text += "\n  }\n";
    if (material.texture) {
      std::filesystem::path png = textureFileFor(file, material);
      files.add(png).write(encodePng(*material.texture));
      // POV-Ray 3.7 takes transparency from the PNG's alpha channel.
      text += fmt::format("  uv_mapping texture {{ pigment {{ image_map {{ png \"{}\" interpolate 2{} }} }} "
                          "finish {{ diffuse 0.8 ambient 0.08 }} }}\n",
                          png.filename().string(), material.repeat ? "" : " once");
    } else {
      text += fmt::format("  texture {{ pigment {{ color rgb <{:.3f},{:.3f},{:.3f}> }} finish {{ diffuse 0.8 ambient 0.08 }} }}\n",
                          material.baseColor.r, material.baseColor.g, material.baseColor.b);
    }
    text += "}\n";
    pov.write(text);
  }
  files.commit();
}

}  // namespace eco
