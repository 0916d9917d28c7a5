#include "render/scene/seen_forest.hpp"

#include <algorithm>

#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

namespace eco {

bool mayBeDrawn(const Forest& forest, std::size_t i, const TreeType& type, glm::vec3 eye,
                float pixelsPerRadian, const LodSettings& lod, float nearer_m) {
  const glm::vec3 centre(drawnBounds(forest, i, type));
  const float nearest = std::max(glm::length(centre - eye) - nearer_m, 0.0f);
  return mayReachMinPixels(type.height_m * forest.scaleY[i], nearest, pixelsPerRadian, lod);
}

void SeenForestSum::add(const Forest& part, const std::function<TreeSeen(std::size_t)>& seen) {
  floor_.add(part);
  verdicts_.resize(part.size());
  tbb::parallel_for(std::size_t{0}, part.size(), [&](std::size_t i) { verdicts_[i] = seen(i); });
  for (std::size_t i = 0; i < part.size(); ++i) {
    switch (verdicts_[i]) {
      case TreeSeen::Shown:
        seen_.shown.append(part, i);
        break;
      case TreeSeen::Culled:
        ++seen_.culled;
        break;
      case TreeSeen::TooSmall:
        ++seen_.tooSmall;
        break;
    }
  }
}

SeenForest SeenForestSum::done() && {
  seen_.floor = floor_.floor();
  return std::move(seen_);
}

SeenForest forestSeenFrom(const RunFolder& run, int year, const TreeLibrary& library,
                          const Grid& grid, const Camera& camera, FrameSize frame,
                          const LodSettings& lod) {
  const Frustum frustum = Frustum::fromMatrix(
      camera.projection(static_cast<float>(frame.width) / frame.height) * camera.view());
  const float pixelsPerRadian = camera.pixelsPerRadian(frame.height);
  SeenForestSum sum(library, grid);
  forEachForestBatch(run, year, library, [&](const Forest& batch) {
    sum.add(batch, [&](std::size_t i) {
      const TreeType& type = library.type(batch.type[i]);
      if (mayBeDrawn(batch, i, type, camera.position, pixelsPerRadian, lod)) return TreeSeen::Shown;
      const glm::vec4 bounds = drawnBounds(batch, i, type);
      return frustum.intersectsSphere(glm::vec3(bounds), bounds.w) ? TreeSeen::TooSmall
                                                                   : TreeSeen::Culled;
    });
  });
  return std::move(sum).done();
}

SeenForest wholeForest(Forest forest, const TreeLibrary& library, const Grid& grid) {
  SeenForest seen;
  seen.floor = canopyFloor(forest, library, grid);
  seen.shown = std::move(forest);
  return seen;
}

}  // namespace eco
