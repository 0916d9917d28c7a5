#include "core/image.hpp"

#include <algorithm>
#include <cmath>

#include <stb/stb_image_write.h>

#include "core/error.hpp"

namespace eco {

void Image::set(int x, int y, glm::vec4 color) {
  ECO_ASSERT(x >= 0 && x < width && y >= 0 && y < height, "pixel " << x << "," << y);
  std::uint8_t* pixel = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  for (int c = 0; c < 4; ++c)
    pixel[c] = static_cast<std::uint8_t>(std::lround(std::clamp(color[c], 0.0f, 1.0f) * 255.0f));
}

glm::vec4 Image::get(int x, int y) const {
  const std::uint8_t* pixel = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  return glm::vec4(pixel[0], pixel[1], pixel[2], pixel[3]) / 255.0f;
}

std::vector<std::uint8_t> Image::rgb() const {
  std::vector<std::uint8_t> out;
  out.reserve(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0; i < rgba.size(); i += 4)
    out.insert(out.end(), rgba.begin() + i, rgba.begin() + i + 3);
  return out;
}

glm::vec4 Image::meanOpaqueColor() const {
  glm::dvec4 sum(0.0);
  std::size_t count = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::vec4 c = get(x, y);
      if (c.a < 0.5f) continue;
      sum += glm::dvec4(c);
      ++count;
    }
  return count == 0 ? glm::vec4(0.0f) : glm::vec4(sum / static_cast<double>(count));
}

std::vector<std::uint8_t> encodePng(const Image& image) {
  std::vector<std::uint8_t> bytes;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    auto* begin = static_cast<std::uint8_t*>(data);
    out->insert(out->end(), begin, begin + size);
  };
  int ok = stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(),
                                  image.width * 4);
  ECO_ASSERT(ok != 0,
             "PNG encoding failed for a " << image.width << "x" << image.height << " image");
  return bytes;
}

}  // namespace eco
