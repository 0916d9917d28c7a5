#include "render/gl/billboards.hpp"

#include <algorithm>
#include <vector>

#include "render/gl/forest_renderer.hpp"
#include "render/gl/frame_uniforms.hpp"

namespace eco {

Billboards bakeBillboards(const TreeLibrary& library, std::span<const int> types,
                          const ImpostorSettings& settings) {
  const FrameUniformBuffer uniforms;
  // Only the two frames each picture shows are baked, one type at a time: the atlases of
  // every type at 256 pixels a frame would take gigabytes.
  ForestRenderer renderer(library, settings, uniforms);  // bakes no atlas unless it draws
  Billboards billboards{settings, {}};
  const std::array<glm::ivec2, 2> frames = billboardFrames(settings.frames);
  const int tile = settings.tilePixels;
  const auto stride = static_cast<std::size_t>(tile) * 4;
  billboards.textures.resize(library.typeCount());
  std::vector<std::vector<Image>> sourceFrames(library.typeCount());
  for (const int t : types) {
    // The variants of a species and age class show their source type's frames.
    const auto source = static_cast<std::size_t>(renderer.impostorSource(t));
    if (sourceFrames[source].empty())
      sourceFrames[source] = renderer.bakeFrameImages(static_cast<int>(source), frames);
    Image& picture = billboards.textures[t] = Image(2 * tile, tile);
    for (std::size_t view = 0; view < frames.size(); ++view) {
      const Image& frame = sourceFrames[source][view];
      for (int y = 0; y < tile; ++y)
        std::copy_n(
            frame.rgba.begin() + static_cast<std::ptrdiff_t>(y * stride), stride,
            picture.rgba.begin() + static_cast<std::ptrdiff_t>(y * 2 * stride + view * stride));
    }
  }
  return billboards;
}

}  // namespace eco
