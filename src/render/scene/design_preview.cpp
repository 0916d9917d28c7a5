#include "render/scene/design_preview.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "core/error.hpp"
#include "core/frames.hpp"
#include "core/stopwatch.hpp"
#include "core/thread_priority.hpp"
#include "render/scene/camera_controller.hpp"
#include "render/scene/crown_shade.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/impostor.hpp"

namespace eco {
namespace {

// The patch of ground reaches to the horizon the cameras see: 2 km square, the edited tree
// at its centre and the row to the east.
constexpr double kGround_m = 2000.0, kCell_m = 50.0;  // flat: big cells cost nothing
constexpr double kEditedEast_m = 1000.0, kRowNorth_m = 1000.0;
constexpr double kGap_m = 3.0;  // between neighbouring crowns

struct BuiltTree {
  TreeType type;
  TreeType hint;
  std::size_t leaves = 0;  // of its rest pose
  SkeletonMeasures measures;
};

// The mesh a level of a species shows: an impostor is baked from a mesh level
// (impostor.hpp).
int meshLevelOf(const Species& species, int level) {
  return level == kLevelImpostor ? impostorBakeLevel(species, ImpostorSettings{}.bakeLod) : level;
}

// One tree of the preview; its hint sleeves too when a hint is asked for.
BuiltTree buildTree(const Species& species, int speciesIndex, std::uint64_t seed, double age,
                    int level, const std::optional<HintInterval>& hint) {
  const int meshLevel = meshLevelOf(species, level);
  std::vector<SkeletonMesher> meshers{[&](const TreeSkeleton& skeleton, TreeMesh& mesh) {
    buildLodInto(skeleton, species, meshLevel, mesh);
  }};
  const bool sleeves = hint && level != kLevelImpostor;  // the hint is for meshes only
  if (sleeves)
    meshers.push_back([&](const TreeSkeleton& skeleton, TreeMesh& mesh) {
      mesh.parts.clear();
      mesh.parts.push_back(hintSleeves(skeleton, hintedSegments(skeleton, *hint)));
      mesh.dropEmptyParts();
    });
  BuiltTree tree;
  TreeSkeleton rest;
  // The preview's wind is the species' own sway; the scene adds no directed wind. A tree
  // that does not sway (the paper's beech and pine: k_f = 1) needs only its rest pose.
  const bool sways = species.wind.undirected_ws * (1.0 - species.wind.flexibility) > 0.0;
  std::vector<WindMesh> meshes =
      buildWindMeshes(species, seed, age, meshers, nullptr, &rest, sways);
  tree.measures = measure(rest);
  tree.leaves = rest.leaves.size();
  tree.type.species = speciesIndex;
  tree.type.seed = seed;
  tree.type.age = age;
  tree.type.meshes.lods[meshLevel] = std::move(meshes[0]);
  shadeVertices(tree.type.meshes.lods[meshLevel], CrownShade(rest, species));  // as the library
  measureType(tree.type, tree.measures);
  tree.hint.species = kPreviewHint;
  tree.hint.seed = seed;
  tree.hint.age = age;
  if (sleeves) tree.hint.meshes.lods[meshLevel] = std::move(meshes[1]);
  measureType(tree.hint, tree.measures);
  return tree;
}

}  // namespace

int previewTypeCount(int comparedSpecies) {
  return kPreviewRowFirst + static_cast<int>(std::size(kPreviewRowAges)) + kPreviewRowVariants +
         comparedSpecies;
}

std::vector<Species> previewSpecies(const Species& edited, const std::vector<Species>& compared) {
  std::vector<Species> species{edited, edited};
  species[kPreviewHint].appearance.barkColor = kHintColor;
  species[kPreviewHint].appearance.barkRoughness = 0.0;
  species.insert(species.end(), compared.begin(), compared.end());
  return species;
}

PreviewScene buildPreview(const Species& edited, const PreviewSettings& settings) {
  using Clock = std::chrono::steady_clock;
  PreviewScene scene;
  scene.settings = settings;
  const auto start = Clock::now();
  BuiltTree main =
      buildTree(edited, kPreviewEdited, settings.seed, settings.age, settings.level, settings.hint);
  scene.stats.buildMs = millisecondsSince(start);
  scene.stats.segments = main.measures.segments;
  scene.stats.leaves = main.leaves;
  scene.stats.height_m = main.measures.height_m;
  scene.stats.crownRadius_m = main.measures.crownRadius_m;
  scene.stats.triangles =
      main.type.meshes.lods[meshLevelOf(edited, settings.level)].triangleCount();
  scene.types.push_back(std::move(main.type));
  scene.types.push_back(std::move(main.hint));
  return scene;
}

void addPreviewRow(PreviewScene& scene, const Species& edited,
                   const std::vector<Species>& compared) {
  ECO_ASSERT(!scene.complete && scene.types.size() == kPreviewRowFirst, scene.types.size());
  const PreviewSettings& settings = scene.settings;
  scene.complete = true;

  // The row: its own seed at younger ages, other seeds at its age, then each compared
  // species at the same seed and age.
  struct RowTree {
    const Species* species;
    int index;
    std::uint64_t seed;
    double age;
  };
  std::vector<RowTree> row;
  for (double age : kPreviewRowAges)
    row.push_back({&edited, kPreviewEdited, settings.seed, age * settings.age});
  for (int v = 1; v <= kPreviewRowVariants; ++v)
    row.push_back(
        {&edited, kPreviewEdited, settings.seed + static_cast<std::uint64_t>(v), settings.age});
  for (std::size_t c = 0; c < compared.size(); ++c)
    row.push_back({&compared[c], kPreviewComparedSpeciesFirst + static_cast<int>(c), settings.seed,
                   settings.age});
  std::vector<TreeType> built(row.size());
  tbb::parallel_for(std::size_t{0}, row.size(), [&](std::size_t i) {
    built[i] = buildTree(*row[i].species, row[i].index, row[i].seed, row[i].age, settings.level,
                         std::nullopt)
                   .type;
  });
  scene.types.insert(scene.types.end(), std::make_move_iterator(built.begin()),
                     std::make_move_iterator(built.end()));

  double east = kEditedEast_m;
  scene.bases.push_back(worldFromMap(east, kRowNorth_m, 0.0));
  scene.bases.push_back(scene.bases.back());  // the hint stands on the edited tree
  float previousRadius = scene.types[kPreviewEdited].crownRadius_m;
  for (std::size_t t = kPreviewRowFirst; t < scene.types.size(); ++t) {
    const float radius = std::max(scene.types[t].crownRadius_m, 0.5f);
    east += previousRadius + radius + kGap_m;
    scene.bases.push_back(worldFromMap(east, kRowNorth_m, 0.0));
    previousRadius = radius;
  }
}

PreviewScene buildCompletePreview(const Species& edited, const std::vector<Species>& compared,
                                  const PreviewSettings& settings) {
  PreviewScene scene = buildPreview(edited, settings);
  addPreviewRow(scene, edited, compared);
  return scene;
}

Forest previewForest(const std::vector<glm::vec3>& bases, bool hint, bool row) {
  Forest forest;
  const std::size_t count =
      row ? bases.size() : std::min<std::size_t>(bases.size(), kPreviewRowFirst);
  for (std::size_t t = 0; t < count; ++t)
    if (hint || static_cast<int>(t) != kPreviewHint)
      forest.addAsBuilt(static_cast<int>(t), bases[t]);
  return forest;
}

Terrain previewGround(const std::vector<glm::vec3>& bases) {
  double east = kGround_m;
  for (const glm::vec3& base : bases) east = std::max(east, mapFromWorld(base).x + kEditedEast_m);
  Terrain ground;
  ground.grid.width = static_cast<int>(std::ceil(east / kCell_m)) + 1;
  ground.grid.height = static_cast<int>(std::ceil(kGround_m / kCell_m)) + 1;
  ground.grid.dx_m = ground.grid.dy_m = kCell_m;
  ground.height_m.assign(ground.grid.cellCount(), 0.0f);
  return ground;
}

Camera OrbitCamera::camera() const {
  Camera camera;
  camera.yaw_deg = yaw_deg;
  camera.pitch_deg = -pitch_deg;
  camera.near_m = std::max(0.05f, 0.01f * distance_m);
  camera.position = target - camera.forward() * distance_m;
  return camera;
}

void OrbitCamera::orbit(float dx_px, float dy_px) {
  yaw_deg = std::fmod(yaw_deg + CameraController::kDegreesPerPixel * dx_px + 360.0f, 360.0f);
  pitch_deg = std::clamp(pitch_deg + CameraController::kDegreesPerPixel * dy_px, -5.0f, 85.0f);
}

void OrbitCamera::zoom(float steps) {
  distance_m = std::clamp(distance_m * std::pow(0.9f, steps), 1.0f, 400.0f);
}

PreviewBuilder::PreviewBuilder(std::vector<Species> compared)
    : compared_(std::move(compared)), worker_([this] { work(); }) {}

PreviewBuilder::~PreviewBuilder() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void PreviewBuilder::request(const Species& edited, std::uint64_t version,
                             const PreviewSettings& settings) {
  {
    std::lock_guard lock(mutex_);
    pending_ = Request{edited, version, settings};
  }
  changed_.notify_all();
}

std::optional<PreviewScene> PreviewBuilder::take(std::chrono::milliseconds wait) {
  std::unique_lock lock(mutex_);
  if (wait.count() > 0)
    changed_.wait_for(lock, wait,
                      [this] { return finished_.has_value() || (!pending_ && !working_); });
  std::optional<PreviewScene> scene = std::move(finished_);
  finished_.reset();
  return scene;
}

double PreviewBuilder::lastBuildMs() const {
  std::lock_guard lock(mutex_);
  return lastBuildMs_;
}

std::chrono::milliseconds PreviewBuilder::worthWaiting() const {
  return std::chrono::milliseconds(lastBuildMs() < 10.0 ? 12 : 0);
}

bool PreviewBuilder::busy() const {
  std::lock_guard lock(mutex_);
  return working_ || pending_.has_value();
}

void PreviewBuilder::work() {
  lowerThisThreadsPriority();
  for (;;) {
    Request request;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return stopping_ || pending_.has_value(); });
      if (stopping_) return;
      request = std::move(*pending_);
      pending_.reset();
      working_ = true;
    }
    // The edited tree first, on its own; then, unless a newer request came meanwhile, the
    // whole scene with the row.
    PreviewScene scene = buildPreview(request.edited, request.settings);
    scene.version = request.version;
    {
      std::lock_guard lock(mutex_);
      lastBuildMs_ = scene.stats.buildMs;
    }
    auto publish = [&](bool last) {
      {
        std::lock_guard lock(mutex_);
        finished_ = scene;  // a complete scene replaces an unshown partial one
        if (last) working_ = false;
      }
      changed_.notify_all();
    };
    const bool newer = [&] {
      std::lock_guard lock(mutex_);
      return pending_.has_value() || stopping_;
    }();
    publish(newer);
    if (newer) continue;
    addPreviewRow(scene, request.edited, compared_);
    publish(true);
  }
}

}  // namespace eco
