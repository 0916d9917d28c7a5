// What the ground cover costs at eye level (docs/rendering.md, "Ground cover"): the
// scenario's terrain planted with TREES trees at random, seen from the ground preset's
// camera, with each quality's radius. Prints the tufts drawn, the scatter's CPU time and the
// whole frame against the same frame without ground cover (best of three). Our goal: the
// ground cover adds at most a quarter to a balanced frame at eye level on llvmpipe, so that
// `view` stays interactive when walking.
// Usage: ground_cover_bench [SCENARIO = valley] [TREES = 10000] [SIZE = 1280x720]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/stopwatch.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/scene_renderer.hpp"
#include "render/scene/frame_size.hpp"
#include "render/scene/tree_clearance.hpp"
#include "sim/conditions/moisture.hpp"
#include "sim/scenario.hpp"
#include "sim/terrain.hpp"

namespace {

using eco::millisecondsSince;

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path scenarioFile =
      argc > 1 ? std::filesystem::path(argv[1])
               : std::filesystem::path(ECOFOREST_DATA_DIR) / "valley.toml";
  const std::size_t trees = argc > 2 ? std::stoul(argv[2]) : 10000;
  const eco::FrameSize size =
      argc > 3 ? eco::parseFrameSize(argv[3]).value_or(eco::FrameSize{}) : eco::FrameSize{};

  const eco::Scenario scenario = eco::loadScenario(scenarioFile);
  const eco::Terrain terrain = eco::loadTerrain(scenario);
  const eco::TreeLibrary library(eco::loadLibrarySpecies(scenario), {});
  const eco::Forest forest = eco::demoForest(terrain, library, trees, scenario.seed);
  eco::HeadlessGl gl;
  const eco::RenderTarget target = eco::RenderTarget::create(size.width, size.height);
  const eco::Camera camera = eco::groundCamera(terrain, forest, library);
  const float aspect = static_cast<float>(size.width) / static_cast<float>(size.height);
  const eco::Frustum frustum = eco::Frustum::fromMatrix(camera.projection(aspect) * camera.view());

  std::printf("%s, %dx%d, %zu trees, ground camera\n", eco::glDescription().c_str(), size.width,
              size.height, trees);
  std::printf("%9s | %7s %7s | %10s %10s | %12s %9s\n", "quality", "radius", "tufts", "scatter ms",
              "frame ms", "without ms", "added");
  for (eco::RenderQuality quality :
       {eco::RenderQuality::Draft, eco::RenderQuality::Balanced, eco::RenderQuality::High}) {
    eco::SceneRenderer renderer(terrain, scenario.climate.latitude_deg, &library,
                                eco::impostorSettingsFor(quality));
    renderer.setGroundMoisture(eco::moistureOf(terrain, scenario.climate.annualPrecipitation_mm));
    renderer.setForestFloor(forest);
    eco::RenderOptions options;
    options.lod.switchPixels = eco::switchPixelsFor(quality);
    options.groundCover = eco::groundCoverFor(quality);
    eco::RenderOptions bare = options;
    bare.groundCover.radius_m = 0.0f;
    renderer.render(&forest, camera, options, target);  // warm-up: first use of buffers
    double withMs = 1e30, withoutMs = 1e30, scatterMs = 1e30;
    std::size_t tufts = 0;
    for (int repeat = 0; repeat < 3; ++repeat) {
      const eco::FrameStats stats = renderer.render(&forest, camera, options, target);
      withMs = std::min(withMs, stats.frameMs);
      tufts = stats.groundTufts;
      withoutMs = std::min(withoutMs, renderer.render(&forest, camera, bare, target).frameMs);
      const auto start = std::chrono::steady_clock::now();
      const std::size_t scattered =
          renderer.groundCover().scatter(camera.position, frustum, options.groundCover).size();
      scatterMs = std::min(scatterMs, millisecondsSince(start));
      if (scattered != tufts) std::fprintf(stderr, "ground_cover_bench: scatter disagrees\n");
    }
    std::printf("%9s | %6.0fm %7zu | %10.1f %10.1f | %12.1f %8.0f%%\n",
                std::string(eco::toString(quality)).c_str(), options.groundCover.radius_m, tufts,
                scatterMs, withMs, withoutMs, 100.0 * (withMs - withoutMs) / withoutMs);
  }
  return 0;
}
