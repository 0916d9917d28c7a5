// How close ecoforest's pictures are to its own full-detail picture, in a viewer's terms:
// fixed views of a run's last snapshot (the valley at year 150) and of 10,000 trees planted
// on its terrain, drawn at each quality (draft, balanced, high) and with every tree at LOD0,
// compared as the mean difference per channel (0..255) and the SSIM of the luma after 4x
// downsampling (core/image_metrics), with every picture saved. Goals (issue 16): at high a
// mean difference of at most 6 and an SSIM of at least 0.85 in every view; at balanced at
// most 10 and 0.7. The frame time of each quality is printed as well (llvmpipe here), and
// the mean difference after the 4x downsampling too. The row "1 px shift" is the reference
// against itself moved one pixel: the floor below which only the same leaves drawn onto the
// same pixels can go (a view of far crowns, whose leaves are smaller than a pixel, differs
// from itself so moved by more than the goals allow).
//
// The all-LOD0 reference of a whole run takes tens of minutes on llvmpipe, so the
// reference draws every tree at LOD0 down to REFERENCE_MIN_PIXELS of height (impostors
// below, cross-faded); 0 draws truly every tree at LOD0. For the planted scene both are
// drawn and their difference is printed: the cost of the approximation.
//
// Usage: fidelity_bench [RUN_DIR | SCENARIO.toml = valley.toml] [SIZE = 1280x720]
//                       [REFERENCE_MIN_PIXELS = 8] [OUT_DIR = fidelity] [PLANTED_TREES = 10000]
//                       [VIEWS = low,ground,300m]
// (a scenario: the planted scene only, on its terrain)
//        fidelity_bench --compare A.png B.png   (the same measures of two saved pictures; A
//        may be a finer picture of B's view, k times its size, averaged down to it first)
// --reuse-references (anywhere): read the references already saved in OUT_DIR instead of
// drawing them again (they take minutes; the qualities seconds), e.g. while tuning a level.
// --antialias N|auto (anywhere): every picture, references included, with N samples a
// pixel (render's --antialias), so both sides are measured without their aliasing.
// --double-reference (anywhere): the row "LOD0 at 2x" as well, the reference drawn at twice
// the size (LOD0 down to twice REFERENCE_MIN_PIXELS) and averaged back down: the floor of
// any picture whose pixels show other leaves (doubleReference below). Saved as
// *_reference_2x.png; it takes about as long again as the reference.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/frames.hpp"
#include "core/image_metrics.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/gl_objects.hpp"
#include "render/gl/scene_renderer.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/frame_size.hpp"
#include "render/scene/tree_clearance.hpp"
#include "sim/image_io.hpp"
#include "sim/run/run_folder.hpp"
#include "sim/scenario.hpp"
#include "sim/terrain.hpp"

namespace {

struct View {
  std::string name;
  eco::Camera camera;
};

// The benchmark's three views: the low preset, the ground preset among the trees, and a
// view from 300 m above the ground a sixth of the way up the map, looking north 25 degrees
// down.
std::vector<View> viewsOf(const eco::Terrain& terrain, const eco::Forest& forest,
                          const eco::TreeLibrary& library) {
  const eco::Grid& g = terrain.grid;
  const double east = 0.5 * g.eastOf(g.width - 1), north = g.northOf(0) / 6.0;
  eco::Camera high;
  high.position = eco::worldFromMap(east, north, terrain.altitudeAt(east, north) + 300.0);
  high.pitch_deg = -25.0f;
  return {{"low", eco::presetCamera(eco::CameraPreset::Low, terrain)},
          {"ground", eco::groundCamera(terrain, forest, library)},
          {"300m", high}};
}

// Each quality draws with the impostors it bakes (impostorSettingsFor); the reference's
// few impostors, under REFERENCE_MIN_PIXELS, are baked from LOD0.
struct Renderers {
  eco::SceneRenderer lod0Baked, lod1Baked;
  eco::SceneRenderer& of(eco::RenderQuality quality) {
    return eco::impostorSettingsFor(quality).bakeLod == 0 ? lod0Baked : lod1Baked;
  }
};

struct Picture {
  eco::Image image;
  eco::FrameStats stats;
};

Picture draw(eco::SceneRenderer& renderer, const eco::Forest& forest, const eco::Camera& camera,
             const eco::RenderOptions& options, const eco::RenderTarget& target) {
  const eco::FrameStats stats = renderer.render(&forest, camera, options, target);
  return {eco::readPixels(target), stats};
}

eco::RenderOptions referenceOptions(float minPixels) {
  eco::RenderOptions options;
  if (minPixels <= 0.0f)
    options.lod.forcedLevel = 0;
  else
    options.lod.switchPixels = {minPixels, minPixels, minPixels};
  return options;
}

// The picture moved one pixel to the right (its first column kept). The reference against
// itself so moved is the floor of what any other drawing of the same trees can reach: where
// leaves are smaller than a pixel, each pixel shows one leaf or a gap, and a picture that
// does not draw the same leaves onto the same pixel centres differs by that much.
eco::Image shiftedOnePixel(const eco::Image& image) {
  eco::Image moved = image;
  for (int y = 0; y < image.height; ++y)
    for (int x = 1; x < image.width; ++x) moved.set(x, y, image.get(x - 1, y));
  return moved;
}

// How the benchmark runs, from its command line.
struct BenchSettings {
  float referenceMinPixels = 8.0f;
  std::filesystem::path out = "fidelity";
  std::string only;  // some of low,ground,300m: those only; empty: all
  bool reuseReferences = false;
  // Twice the size of `target`, for the reference drawn finer (--double-reference); none.
  const eco::RenderTarget* doubleTarget = nullptr;
};

// The reference drawn at twice the size and averaged back down, each pixel the mean of
// 2 x 2: the same trees at LOD0 (down to the same height on the screen), a finer picture
// than the reference, whose pixels show other leaves than the reference's pixel centres do.
// How far it lies from the reference is how far any picture of the same trees lies that
// does not sample the very same leaves: the floor for levels of detail, sharper than the one
// pixel shift, which keeps three quarters of each 4 x 4 block's samples.
eco::Image doubleReference(eco::SceneRenderer& renderer, const eco::Forest& forest,
                           const eco::Camera& camera, const BenchSettings& settings,
                           const std::string& stem) {
  const std::string file = stem + "reference_2x.png";
  if (settings.reuseReferences && std::filesystem::exists(file))
    return eco::downsampled(eco::readColorImage(file), 2);
  const eco::RenderOptions options = referenceOptions(2.0f * settings.referenceMinPixels);
  renderer.render(&forest, camera, options, *settings.doubleTarget);
  const eco::Image picture = eco::readPixels(*settings.doubleTarget);
  eco::writeRgb8Image(file, picture);
  return eco::downsampled(picture, 2);
}

void compareScene(const std::string& scene, const eco::Terrain& terrain, const eco::Forest& forest,
                  const eco::TreeLibrary& library, Renderers& renderers,
                  const eco::RenderTarget& target, const BenchSettings& settings,
                  bool checkReference) {
  const float referenceMinPixels = settings.referenceMinPixels;
  for (auto* r : {&renderers.lod0Baked, &renderers.lod1Baked}) r->setForestFloor(forest);
  eco::SceneRenderer& renderer = renderers.lod0Baked;  // the reference's
  for (const View& view : viewsOf(terrain, forest, library)) {
    const std::string stem = (settings.out / (scene + "_" + view.name + "_")).string();
    const glm::dvec3 at = eco::mapFromWorld(view.camera.position);
    if (!settings.only.empty() && settings.only.find(view.name) == std::string::npos) continue;
    // The camera as `ecoforest render --camera` takes it, to draw the same view.
    std::printf("%s, %s view: --camera %.9g,%.9g,%.9g,%.9g,%.9g\n", scene.c_str(),
                view.name.c_str(), at.x, at.y, at.z, view.camera.yaw_deg, view.camera.pitch_deg);
    renderer.render(&forest, view.camera, eco::RenderOptions{}, target);  // warm-up
    const bool reuse = settings.reuseReferences && std::filesystem::exists(stem + "reference.png");
    const Picture reference =
        reuse ? Picture{eco::readColorImage(stem + "reference.png"), {}}
              : draw(renderer, forest, view.camera, referenceOptions(referenceMinPixels), target);
    if (!reuse) eco::writeRgb8Image(stem + "reference.png", reference.image);
    const eco::Image referenceSmall = eco::downsampled(reference.image, 4);
    auto row = [&](const char* label, const Picture& p) {
      const eco::Image small = eco::downsampled(p.image, 4);
      std::printf(
          "  %-10s %10.0f ms %14zu triangles   mean diff %6.2f (4x: %5.2f)   SSIM %.3f (4x: "
          "%.3f)\n",
          label, p.stats.frameMs, p.stats.triangles(),
          eco::meanAbsoluteDifference(p.image, reference.image),
          eco::meanAbsoluteDifference(small, referenceSmall),
          eco::structuralSimilarity(p.image, reference.image),
          eco::structuralSimilarity(small, referenceSmall));
    };
    row("reference", reference);
    row("1 px shift", {shiftedOnePixel(reference.image), {}});
    if (settings.doubleTarget)
      row("LOD0 at 2x", {doubleReference(renderer, forest, view.camera, settings, stem), {}});
    if (checkReference && referenceMinPixels > 0.0f && !reuse) {
      const Picture all = draw(renderer, forest, view.camera, referenceOptions(0.0f), target);
      eco::writeRgb8Image(stem + "all_lod0.png", all.image);
      row("all LOD0", all);
    }
    for (eco::RenderQuality quality :
         {eco::RenderQuality::Draft, eco::RenderQuality::Balanced, eco::RenderQuality::High}) {
      eco::RenderOptions options;
      options.lod.switchPixels = eco::switchPixelsFor(quality);
      const Picture p = draw(renderers.of(quality), forest, view.camera, options, target);
      const std::string name(eco::toString(quality));
      eco::writeRgb8Image(stem + name + ".png", p.image);
      row(name.c_str(), p);
    }
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  // A flag anywhere on the line: whether it was given, taken off the arguments.
  auto takeFlag = [&args](const char* name) {
    const auto flag = std::find(args.begin(), args.end(), name);
    if (flag == args.end()) return false;
    args.erase(flag);
    return true;
  };
  BenchSettings settings;
  settings.reuseReferences = takeFlag("--reuse-references");
  const bool doubleReference = takeFlag("--double-reference");
  int samples = 1;
  if (const auto flag = std::find(args.begin(), args.end(), "--antialias");
      flag != args.end() && flag + 1 != args.end()) {
    samples = *(flag + 1) == "auto" ? eco::kAutoSamples : std::stoi(*(flag + 1));
    args.erase(flag, flag + 2);
  }
  argc = static_cast<int>(args.size());
  if (argc == 4 && args[1] == "--compare") {  // two saved pictures
    eco::Image a = eco::readColorImage(args[2]);
    const eco::Image b = eco::readColorImage(args[3]);
    // A finer picture of the same view (A k times B's size) is averaged down to B's first.
    if (const int k = a.width / std::max(b.width, 1);
        k > 1 && a.width == k * b.width && a.height == k * b.height) {
      a = eco::downsampled(a, k);
      std::printf("A averaged down %dx to B's size\n", k);
    }
    const eco::Image aSmall = eco::downsampled(a, 4), bSmall = eco::downsampled(b, 4);
    std::printf("mean diff %.2f (4x: %.2f)   SSIM %.3f (4x: %.3f)\n",
                eco::meanAbsoluteDifference(a, b), eco::meanAbsoluteDifference(aSmall, bSmall),
                eco::structuralSimilarity(a, b), eco::structuralSimilarity(aSmall, bSmall));
    return 0;
  }
  const std::filesystem::path source =
      argc > 1 ? std::filesystem::path(args[1])
               : std::filesystem::path(ECOFOREST_DATA_DIR) / "valley.toml";
  const eco::FrameSize size =
      argc > 2 ? eco::parseFrameSize(args[2]).value_or(eco::FrameSize{}) : eco::FrameSize{};
  if (argc > 3) settings.referenceMinPixels = std::stof(args[3]);
  if (argc > 4) settings.out = args[4];
  const std::size_t planted = argc > 5 ? std::stoul(args[5]) : 10000;
  if (argc > 6) settings.only = args[6];
  std::filesystem::create_directories(settings.out);

  std::optional<eco::RunFolder> run;
  if (source.extension() != ".toml") run = eco::openRunFolder(source);
  const eco::Scenario scenario = run ? run->scenario : eco::loadScenario(source);
  const eco::Terrain terrain = eco::loadTerrain(scenario);
  const eco::TreeLibrary library(eco::loadLibrarySpecies(scenario), {});
  eco::HeadlessGl gl;
  Renderers renderers{{terrain, scenario.climate.latitude_deg, &library,
                       eco::impostorSettingsFor(eco::RenderQuality::High)},
                      {terrain, scenario.climate.latitude_deg, &library,
                       eco::impostorSettingsFor(eco::RenderQuality::Balanced)}};
  const eco::RenderTarget target = eco::RenderTarget::create(size.width, size.height, 0, samples);
  std::optional<eco::RenderTarget> doubleTarget;
  if (doubleReference) {
    doubleTarget = eco::RenderTarget::create(2 * size.width, 2 * size.height, 0, samples);
    settings.doubleTarget = &*doubleTarget;
  }
  std::printf("%s, %dx%d, %d sample%s a pixel, reference: LOD0 down to %.0f px\n",
              eco::glDescription().c_str(), size.width, size.height, target.samples,
              target.samples == 1 ? "" : "s", settings.referenceMinPixels);

  const eco::Forest plantedForest = eco::demoForest(terrain, library, planted, scenario.seed);
  compareScene("planted", terrain, plantedForest, library, renderers, target, settings, true);
  if (run) {
    const int year = run->snapshotYears.back();
    const eco::Forest forest =
        eco::forestFromSnapshot(eco::readSnapshot(*run, year), library, source.string());
    compareScene("run_year" + std::to_string(year), terrain, forest, library, renderers, target,
                 settings, false);
  }
  return 0;
}
