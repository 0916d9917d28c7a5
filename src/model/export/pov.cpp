// A POV-Ray 3.7 scene: the tree as mesh2 objects with image-mapped textures, a camera
// framing the tree, a sun and a sky, on a ground plane. POV-Ray is left-handed (y up, z
// away from the viewer), so z is mirrored; its image origin is bottom-left, so v is flipped.
#include <fmt/format.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/angles.hpp"
#include "core/atomic_file.hpp"
#include "model/export/tree_export.hpp"

namespace eco {

void writePov(const TreeMesh& mesh, const std::vector<Material>& materials,
              const std::filesystem::path& file) {
  AtomicFileSet files;
  AtomicFile& scene = files.add(file);
  // Frame the whole tree in a 40-degree view from the south-east, a little above its middle.
  Bounds b = boundsOf(mesh);
  glm::vec3 center = 0.5f * (b.min + b.max);
  float radius = 0.5f * glm::length(b.max - b.min);
  float distance = 1.15f * radius / std::tan(radians(20.0f)) + 0.5f;
  glm::vec3 eye = center + distance * glm::normalize(glm::vec3(0.45f, 0.12f, 1.0f));
  glm::vec3 sun = center + 4.0f * distance * glm::normalize(glm::vec3(0.6f, 1.0f, 0.5f));
  glm::vec3 fill = center + 4.0f * distance * glm::normalize(glm::vec3(-0.8f, 0.6f, -0.3f));
  auto pov = [](glm::vec3 v) { return fmt::format("<{:.3f}, {:.3f}, {:.3f}>", v.x, v.y, -v.z); };

  scene.write(
      fmt::format("// ecoforest tree; render with: povray +I{} +W800 +H800 +A\n"
                  "#version 3.7;\n"
                  "global_settings {{ assumed_gamma 1.0 }}\n"
                  "camera {{ location {} look_at {} angle 40 }}\n"
                  "light_source {{ {} color rgb <1.0, 0.97, 0.9> }}\n"
                  "light_source {{ {} color rgb 0.35 shadowless }}\n"
                  "sky_sphere {{ pigment {{ gradient y color_map {{ [0 color rgb <0.75, 0.85, "
                  "1.0>] [1 color rgb <0.3, 0.5, 0.9>] }} }} }}\n"
                  "plane {{ y, 0 pigment {{ color rgb <0.35, 0.42, 0.25> }} }}\n",
                  file.filename().string(), pov(eye), pov(center), pov(sun), pov(fill)));

  std::string text;
  for (std::size_t p = 0; p < mesh.parts.size(); ++p) {
    const MeshPart& part = mesh.parts[p];
    const Material& material = materials[p];
    text.clear();
    text += fmt::format("// {}\nmesh2 {{\n  vertex_vectors {{ {}", material.name,
                        part.positions.size());
    for (glm::vec3 v : part.positions)
      text += fmt::format(",\n<{:.5f},{:.5f},{:.5f}>", v.x, v.y, -v.z);
    text += fmt::format("\n  }}\n  normal_vectors {{ {}", part.normals.size());
    for (glm::vec3 n : part.normals)
      text += fmt::format(",\n<{:.4f},{:.4f},{:.4f}>", n.x, n.y, -n.z);
    text += fmt::format("\n  }}\n  uv_vectors {{ {}", part.uvs.size());
    for (glm::vec2 t : part.uvs) text += fmt::format(",\n<{:.4f},{:.4f}>", t.x, 1.0f - t.y);
    text += fmt::format("\n  }}\n  face_indices {{ {}", part.triangleCount());
    for (std::size_t i = 0; i < part.indices.size(); i += 3)
      text +=
          fmt::format(",\n<{},{},{}>", part.indices[i], part.indices[i + 1], part.indices[i + 2]);
    text += "\n  }\n";
    if (material.texture) {
      std::filesystem::path png = textureFileFor(file, material);
      files.add(png).write(encodePng(*material.texture));
      // POV-Ray 3.7 takes transparency from the PNG's alpha channel.
      text += fmt::format(
          "  uv_mapping texture {{ pigment {{ image_map {{ png \"{}\" interpolate 2{} }} }} "
          "finish {{ diffuse 0.8 ambient 0.08 }} }}\n",
          png.filename().string(), material.repeat ? "" : " once");
    } else {
      text += fmt::format(
          "  texture {{ pigment {{ color rgb <{:.3f},{:.3f},{:.3f}> }} finish {{ diffuse 0.8 "
          "ambient 0.08 }} }}\n",
          material.baseColor.r, material.baseColor.g, material.baseColor.b);
    }
    text += "}\n";
    scene.write(text);
  }
  files.commit();
}

}  // namespace eco
