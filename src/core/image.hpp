// A small RGBA8 image, the currency of procedural textures, and PNG encoding into memory.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

namespace eco {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // row-major, row 0 at the top, 4 bytes per pixel

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  // Components in [0, 1]; clamped and rounded to 8 bits.
  void set(int x, int y, glm::vec4 color);
  glm::vec4 get(int x, int y) const;
  // Mean colour over pixels whose alpha is at least half.
  glm::vec4 meanOpaqueColor() const;
  // The pixels without alpha, 3 bytes each, row 0 first (for RGB files and video encoders).
  std::vector<std::uint8_t> rgb() const;
};

std::vector<std::uint8_t> encodePng(const Image& image);

}  // namespace eco
