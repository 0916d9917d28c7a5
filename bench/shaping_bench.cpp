// What shaping trees by their site costs and how near the renderer comes to the exact shaped
// model (issue 21; docs/rendering.md "Trees shaped by their site").
//
// 1. The lean's fidelity, per species of the scenario at its oldest age class: the renderer
//    draws a leaning tree as its upright mesh plus multiples of the bend bases, where the
//    exact shaped model is the CPU model grown with the lean in its directed vector. For
//    lean lengths up to kPhototropism_wg + kWindLean_wg (the most a site gives) it prints how
//    far the foliage's centre moves in the exact model, and the error of the instance's
//    centre and the mean and 95th-percentile distance of its LOD0 vertices from the exact
//    model's, all in % of the tree's height: with the bases along their straight line
//    (lean / kBendBasis_wg) and as drawn (the type's measured LeanResponse).
// 2. A run (its last snapshot), drawn with shaping on and off: the tree library's build time
//    and type count, the renderer's setup (uploading the meshes, baking the impostors), what
//    it holds on the GPU (meshes, impostor atlases), and the frame time
//    of the low and overview views (best of three, this machine's OpenGL: llvmpipe without a
//    GPU).
//
// Usage: shaping_bench [RUN_DIR | SCENARIO.toml = valley.toml] [YEARS (the scenario's)]
//                      [SIZE = 1280x720] [QUALITY = balanced]
// (a scenario is grown first, as `ecoforest run` grows it, into the temporary directory)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "bench_run.hpp"
#include "core/stopwatch.hpp"
#include "model/mesh/lod.hpp"
#include "model/skeleton.hpp"
#include "model/tree_generator.hpp"
#include "model/tree_shaping.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/scene_renderer.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/frame_size.hpp"
#include "render/scene/tree_library.hpp"
#include "render/scene/wind_mesh.hpp"
#include "sim/run/run_folder.hpp"
#include "sim/terrain.hpp"

namespace {

using eco::millisecondsSince;

double mebibytes(std::size_t bytes) {
  return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

struct LeanFidelity {
  double exactShift = 0.0;    // of the foliage's centre in the exact model
  double centreError = 0.0;   // between the instance's foliage centre and the exact one
  double meanDistance = 0.0;  // over LOD0's vertices
  double distance95 = 0.0;
};

// The instance (rest + multiples of the bend bases) against the exact model grown with `lean`
// (toward east), in % of the rest tree's height; nullopt where the topology changed.
std::optional<LeanFidelity> leanFidelity(const eco::Species& species, std::uint64_t seed,
                                         double age, const eco::WindMesh& rest, float height_m,
                                         double lean, float bases) {
  eco::TreeSkeleton skeleton;
  eco::buildTreeInto(species, eco::windBuildOptions(species, seed, age, {0.0, {lean, 0.0}}, 0.0),
                     skeleton);
  eco::TreeMesh exact;
  eco::buildLodInto(skeleton, species, 0, exact);
  if (!eco::sameTopology(rest, exact)) return std::nullopt;
  std::vector<double> distances;
  for (std::size_t p = 0; p < rest.parts.size(); ++p)
    for (std::size_t v = 0; v < rest.parts[p].vertices.size(); ++v) {
      const eco::TreeVertex& r = rest.parts[p].vertices[v];
      distances.push_back(
          glm::length(r.position + bases * r.bendEast - exact.parts[p].positions[v]));
    }
  LeanFidelity f;
  const double percent = 100.0 / height_m;
  const eco::FoliageCentre restCentre = eco::foliageCentre(rest);
  const glm::dvec3 exactCentre = eco::foliageCentre(exact);
  const glm::dvec3 instanceCentre = restCentre.position + double(bases) * restCentre.bendEast;
  f.exactShift = glm::length(exactCentre - restCentre.position) * percent;
  f.centreError = glm::length(instanceCentre - exactCentre) * percent;
  if (!distances.empty()) {
    double sum = 0.0;
    for (double d : distances) sum += d;
    f.meanDistance = sum / static_cast<double>(distances.size()) * percent;
    const auto at95 = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() * 95 / 100);
    std::nth_element(distances.begin(), at95, distances.end());
    f.distance95 = *at95 * percent;
  }
  return f;
}

// The bases drawn along their straight line (lean / kBendBasis_wg) and as the renderer draws
// them (the type's measured LeanResponse).
void printLeanFidelity(const eco::Scenario& scenario) {
  const eco::LibrarySettings settings;
  const double age = settings.ageClasses.back();
  const std::uint64_t seed = eco::TreeLibrary::variantSeed(0);
  const double most = eco::kPhototropism_wg + eco::kWindLean_wg;
  std::printf(
      "Lean fidelity at age %.2f, variant 0, lean toward east; %% of the tree's height:\n"
      "the foliage centre's shift in the exact model, and the instance's centre error\n"
      "and mean / 95th-percentile vertex distance from it\n",
      age);
  std::printf("%-10s %7s | %7s | %-26s | %-26s\n", "", "", "exact", "  bases along their line",
              "  bases as measured (drawn)");
  std::printf("%-10s %7s | %7s | %8s %8s %8s | %8s %8s %8s\n", "species", "lean wg", "shift",
              "centre", "mean", "95%", "centre", "mean", "95%");
  for (const eco::LibrarySpecies& s : eco::loadLibrarySpecies(scenario)) {
    eco::TreeSkeleton restSkeleton;
    const eco::WindLods lods = eco::buildWindLods(s.model, seed, age, &restSkeleton);
    const eco::WindMesh& lod0 = lods.lods[0];
    const float height_m = static_cast<float>(eco::measure(restSkeleton).height_m);
    const eco::LeanResponse response = eco::measureLeanResponse(s.model, seed, age, 0.0, lod0);
    for (double lean : {0.25 * most, 0.5 * most, 0.75 * most, most}) {
      const auto line = leanFidelity(s.model, seed, age, lod0, height_m, lean,
                                     static_cast<float>(lean / eco::kBendBasis_wg));
      const auto drawn = leanFidelity(s.model, seed, age, lod0, height_m, lean,
                                      response.basesFor({static_cast<float>(lean), 0.0f}).x);
      if (!line || !drawn) {
        std::printf("%-10s %7.2f | topology changed with the lean\n", s.model.name.c_str(), lean);
        continue;
      }
      std::printf("%-10s %7.2f | %6.2f%% | %7.2f%% %7.2f%% %7.2f%% | %7.2f%% %7.2f%% %7.2f%%\n",
                  s.model.name.c_str(), lean, line->exactShift, line->centreError,
                  line->meanDistance, line->distance95, drawn->centreError, drawn->meanDistance,
                  drawn->distance95);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path source =
      argc > 1 ? std::filesystem::path(argv[1])
               : std::filesystem::path(ECOFOREST_DATA_DIR) / "valley.toml";
  std::optional<int> years;
  if (argc > 2 && std::string(argv[2]) != "-") years = std::stoi(argv[2]);
  const eco::FrameSize size =
      argc > 3 ? eco::parseFrameSize(argv[3]).value_or(eco::FrameSize{}) : eco::FrameSize{};
  const std::string qualityName = argc > 4 ? argv[4] : "balanced";
  const std::optional<eco::RenderQuality> quality = eco::parseRenderQuality(qualityName);
  if (!quality) {
    std::fprintf(stderr, "shaping_bench: unknown quality '%s'\n", qualityName.c_str());
    return 2;
  }

  const auto growStart = std::chrono::steady_clock::now();
  const eco::RunFolder run = std::filesystem::is_directory(source)
                                 ? eco::openRunFolder(source)
                                 : eco::bench::growRun(source, "shaping", years);
  if (!std::filesystem::is_directory(source))
    std::printf("grew %s in %.0f s\n", source.filename().c_str(),
                millisecondsSince(growStart) / 1000.0);
  printLeanFidelity(run.scenario);

  const int year = run.snapshotYears.back();
  const eco::TreeSnapshot snapshot = eco::readSnapshot(run, year);
  const eco::Terrain terrain = eco::loadTerrain(run.scenario);
  eco::HeadlessGl gl;
  eco::RenderOptions options;
  options.lod.switchPixels = eco::switchPixelsFor(*quality);
  const eco::RenderTarget target = eco::RenderTarget::create(size.width, size.height);
  std::printf("\n%s, year %d, %zu trees; %s, %dx%d, %s\n", run.dir.c_str(), year,
              snapshot.trees.size(), eco::glDescription().c_str(), size.width, size.height,
              qualityName.c_str());
  std::printf("%-8s | %7s %10s %11s | %10s %13s | %13s %13s\n", "shaping", "built", "library ms",
              "renderer ms", "mesh MiB", "impostor MiB", "low frame ms", "overview ms");
  for (bool shaping : {false, true}) {
    auto start = std::chrono::steady_clock::now();
    const eco::TreeLibrary library(eco::loadLibrarySpecies(run.scenario),
                                   eco::LibrarySettings::shaped(shaping));
    const eco::Forest forest = eco::forestFromSnapshot(snapshot, library, run.dir.string());
    const double libraryMs = millisecondsSince(start);  // with the forest's types built
    start = std::chrono::steady_clock::now();
    eco::SceneRenderer renderer(terrain, run.scenario.climate.latitude_deg, &library,
                                eco::impostorSettingsFor(*quality));
    const double rendererMs = millisecondsSince(start);
    renderer.setForestFloor(forest);
    double frameMs[2];
    int view = 0;
    for (eco::CameraPreset preset : {eco::CameraPreset::Low, eco::CameraPreset::Overview}) {
      const eco::Camera camera = eco::presetCamera(preset, terrain);
      renderer.render(&forest, camera, options, target);  // warm-up: first use of buffers
      frameMs[view] = 1e30;
      for (int repeat = 0; repeat < 3; ++repeat)
        frameMs[view] =
            std::min(frameMs[view], renderer.render(&forest, camera, options, target).frameMs);
      ++view;
    }
    const eco::ForestGpuMemory& memory = renderer.forest()->gpuMemory();
    const std::string built =
        std::to_string(library.builtTypeCount()) + "/" + std::to_string(library.typeCount());
    std::printf("%-8s | %7s %10.0f %11.0f | %10.1f %13.1f | %13.1f %13.1f\n",
                shaping ? "on" : "off", built.c_str(), libraryMs, rendererMs,
                mebibytes(memory.meshBytes), mebibytes(memory.impostorBytes), frameMs[0],
                frameMs[1]);
  }
  return 0;
}
