#include "render/gl/billboards.hpp"

#include <algorithm>

#include "render/gl/forest_renderer.hpp"
#include "render/gl/frame_uniforms.hpp"

namespace eco {

Billboards bakeBillboards(const TreeLibrary& library, const ImpostorSettings& settings) {
  const FrameUniformBuffer uniforms;
  const ForestRenderer renderer(library, settings, uniforms);  // bakes the impostor frames
  Billboards billboards{settings, {}};
  const std::array<glm::ivec2, 2> frames = billboardFrames(settings.frames);
  const int tile = settings.tilePixels;
  const auto stride = static_cast<std::size_t>(tile) * 4;
  for (std::size_t t = 0; t < library.types().size(); ++t) {
    Image& picture = billboards.textures.emplace_back(2 * tile, tile);
    for (std::size_t view = 0; view < frames.size(); ++view) {
      const Image frame = renderer.impostorFrameImage(static_cast<int>(t), frames[view]);
      for (int y = 0; y < tile; ++y)
        std::copy_n(
            frame.rgba.begin() + static_cast<std::ptrdiff_t>(y * stride), stride,
            picture.rgba.begin() + static_cast<std::ptrdiff_t>(y * 2 * stride + view * stride));
    }
  }
  return billboards;
}

}  // namespace eco
