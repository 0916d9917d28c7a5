// Frame time and triangles of the valley forest at 1280x720 on this machine's OpenGL
// (llvmpipe without a GPU): 10k, 100k and 300k trees planted over the valley terrain, with
// LODs and impostors against everything at LOD0. The LOD0-only frame is rendered where it
// is affordable (`lod0-limit` trees) and compared with the LOD frame as a mean pixel
// difference; above that only its triangle count is given. Goals on llvmpipe: 300k trees
// under 1 s a frame, at least 50x fewer triangles than LOD0-only, and a mean difference from
// the LOD0-only frame under 8 of 255 per channel (3 %: leaf-sized detail, not trees, differs).
// Each count's frame is then drawn once more with every pass waited for and timed.
// Usage: render_bench [SCENARIO = valley] [COUNTS = 10000,100000,300000] [LOD0-LIMIT = 10000]
//                     [SIZE = 1280x720] [QUALITY = balanced]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "core/stopwatch.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/scene_renderer.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/frame_size.hpp"
#include "sim/scenario.hpp"
#include "sim/terrain.hpp"

namespace {

using eco::millisecondsSince;

double meanDifference(const eco::Image& a, const eco::Image& b) {
  double sum = 0.0;
  for (std::size_t p = 0; p < a.rgba.size(); p += 4)
    for (int c = 0; c < 3; ++c) sum += std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c]));
  return sum / (3.0 * static_cast<double>(a.rgba.size() / 4));
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path scenarioFile =
      argc > 1 ? std::filesystem::path(argv[1])
               : std::filesystem::path(ECOFOREST_DATA_DIR) / "valley.toml";
  std::vector<std::size_t> counts{10000, 100000, 300000};
  if (argc > 2) {
    counts.clear();
    std::stringstream list(argv[2]);
    for (std::string item; std::getline(list, item, ',');) counts.push_back(std::stoul(item));
  }
  const std::size_t lod0Limit = argc > 3 ? std::stoul(argv[3]) : 10000;
  const eco::FrameSize size =
      argc > 4 ? eco::parseFrameSize(argv[4]).value_or(eco::FrameSize{}) : eco::FrameSize{};
  const int width = size.width, height = size.height;

  const eco::Scenario scenario = eco::loadScenario(scenarioFile);
  const eco::Terrain terrain = eco::loadTerrain(scenario);
  std::vector<eco::LibrarySpecies> species = eco::loadLibrarySpecies(scenario);
  auto start = std::chrono::steady_clock::now();
  const eco::TreeLibrary library(std::move(species), {});
  // Every type built now: the demo forests of every count draw most of them.
  std::vector<int> every(library.typeCount());
  std::iota(every.begin(), every.end(), 0);
  library.build(every);
  const double libraryMs = millisecondsSince(start);
  eco::HeadlessGl gl;
  start = std::chrono::steady_clock::now();
  eco::SceneRenderer renderer(terrain, scenario.climate.latitude_deg, &library);
  const double rendererMs = millisecondsSince(start);
  const eco::RenderTarget target = eco::RenderTarget::create(width, height);
  // Over the valley from its south end, looking down it: near trees to the horizon.
  const eco::Camera camera = eco::presetCamera(eco::CameraPreset::Low, terrain);
  eco::RenderOptions options;
  const std::string qualityName = argc > 5 ? argv[5] : "balanced";
  const std::optional<eco::RenderQuality> quality = eco::parseRenderQuality(qualityName);
  if (!quality) {
    std::fprintf(stderr, "render_bench: unknown quality '%s'\n", qualityName.c_str());
    return 2;
  }
  options.lod.switchPixels = eco::switchPixelsFor(*quality);

  std::printf("%s, %dx%d, %s; tree library %.0f ms (%d types), renderer and impostors %.0f ms\n",
              eco::glDescription().c_str(), width, height, qualityName.c_str(), libraryMs,
              library.typeCount(), rendererMs);
  std::printf("%8s | %9s %9s %9s %9s | %10s %12s %7s | %9s %9s | %9s %8s\n", "trees", "LOD0",
              "LOD1", "LOD2", "impostor", "triangles", "LOD0-only", "ratio", "frame ms", "prepare",
              "LOD0 ms", "mean diff");
  for (std::size_t count : counts) {
    const eco::Forest forest = eco::demoForest(terrain, library, count, scenario.seed);
    renderer.render(&forest, camera, options, target);  // warm-up: first use of buffers
    double frameMs = 1e30, prepareMs = 0.0;
    eco::FrameStats stats;
    for (int repeat = 0; repeat < 3; ++repeat) {
      stats = renderer.render(&forest, camera, options, target);
      if (stats.frameMs < frameMs) frameMs = stats.frameMs, prepareMs = stats.prepareMs;
    }
    const eco::Image lodImage = eco::readPixels(width, height);
    eco::RenderOptions timed = options;
    timed.timePasses = true;
    const eco::FrameStats passes = renderer.render(&forest, camera, timed, target);
    std::string lod0Ms = "-", difference = "-";
    if (count <= lod0Limit) {
      eco::RenderOptions allLod0 = options;
      allLod0.lod.forcedLevel = 0;
      const eco::FrameStats reference = renderer.render(&forest, camera, allLod0, target);
      lod0Ms = std::to_string(static_cast<long>(reference.frameMs));
      char text[32];
      std::snprintf(text, sizeof text, "%.2f",
                    meanDifference(lodImage, eco::readPixels(width, height)));
      difference = text;
    }
    const auto& n = stats.forest.instances;
    const double all = static_cast<double>(stats.forest.lod0Triangles + stats.terrainTriangles);
    std::printf("%8zu | %9zu %9zu %9zu %9zu | %10zu %12.0f %6.0fx | %9.1f %9.1f | %9s %8s\n", count,
                n[0], n[1], n[2], n[3], stats.triangles(), all, all / stats.triangles(), frameMs,
                prepareMs, lod0Ms.c_str(), difference.c_str());
    std::printf("%8s   passes (ms), each waited for:", "");
    for (int p = 0; p < eco::kRenderPassCount; ++p)
      std::printf(" %s %.0f (%.1f M fragments)", eco::kRenderPassNames[p], passes.passMs[p],
                  static_cast<double>(passes.passFragments[p]) * 1e-6);
    std::printf("\n");
  }
  return 0;
}
