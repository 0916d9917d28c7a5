#include "app/scene_source.hpp"

#include <fmt/format.h>

#include "app/data_paths.hpp"
#include "core/error.hpp"
#include "render/scene/tree_clearance.hpp"
#include "sim/conditions/conditions.hpp"
#include "sim/image_io.hpp"

namespace eco {

int SceneSource::defaultYear() const {
  return run && !run->snapshotYears.empty() ? run->snapshotYears.back() : 0;
}

Forest SceneSource::forestOf(int year, std::size_t demoTrees) const {
  if (!library) return {};
  if (run) return forestFromRun(*run, year, *library);
  return demoForest(terrain, *library, demoTrees, scenario.seed);
}

SeenForest SceneSource::forestSeenFrom(int year, std::size_t demoTrees, const Camera& camera,
                                       FrameSize frame, const LodSettings& lod) const {
  if (!library) return {};
  if (run) return eco::forestSeenFrom(*run, year, *library, terrain.grid, camera, frame, lod);
  return wholeForest(forestOf(year, demoTrees), *library, terrain.grid);
}

Forest SceneSource::forestForGroundCamera(int year, std::size_t demoTrees) const {
  if (!library || !run) return forestOf(year, demoTrees);
  return forestFromRun(*run, year, *library, [this](const TreeRow& tree) {
    return groundCameraMaySee(terrain, tree.east_m, tree.north_m);
  });
}

Field SceneSource::overlay(const std::string& name) const {
  if (run) {
    const RunPaths paths{run->dir};
    const std::filesystem::path file = paths.map(name);
    if (!std::filesystem::exists(file)) {
      std::string names;
      for (const std::string& map : paths.mapNames()) names += (names.empty() ? "" : ", ") + map;
      throw InputError({run->dir.string(), 0, "overlay"},
                       fmt::format("the run has no map '{}' (it has: {})", name, names));
    }
    SingleChannelImage image = readSingleChannel(file);
    if (image.width != terrain.grid.width || image.height != terrain.grid.height)
      throw InputError({file.string(), 0, ""}, "the map does not match the terrain's grid");
    return std::move(image.values);
  }
  for (const FieldInfo& info : conditionFieldInfo())
    if (name == info.name) {
      requireMemoryForConditions(terrain.grid, false);
      const ConditionFields fields = computeConditions(terrain, scenario.climate, {});
      return fields.*info.field;
    }
  std::string names;
  for (const FieldInfo& info : conditionFieldInfo())
    names += (names.empty() ? "" : ", ") + std::string(info.name);
  throw InputError({scenario.file.string(), 0, "overlay"},
                   fmt::format("no condition '{}' (there are: {})", name, names));
}

void requireOutputFolder(const std::filesystem::path& out) {
  const std::filesystem::path folder =
      out.parent_path().empty() ? std::filesystem::path(".") : out.parent_path();
  if (!std::filesystem::is_directory(folder))
    throw InputError({out.string(), 0, "--out"}, "its folder does not exist");
}

RunFolder openRunArgument(const std::string& run) {
  if (!std::filesystem::is_directory(run))
    throw InputError({run, 0, ""}, "no such run folder (make one with `ecoforest run`)");
  return openRunFolder(run);
}

SceneSource openRunSource(const std::string& run) {
  return sceneSourceOf(openRunArgument(run));
}

SceneSource sceneSourceOf(RunFolder run) {
  SceneSource source;
  source.scenario = run.scenario;
  source.run = std::move(run);
  source.terrain = loadTerrain(source.scenario);
  return source;
}

SceneSource openSceneSource(const std::string& runOrScenario) {
  if (std::filesystem::is_directory(runOrScenario))
    return sceneSourceOf(openRunFolder(runOrScenario));
  SceneSource source;
  source.scenario = loadScenario(resolveScenario(runOrScenario));
  source.terrain = loadTerrain(source.scenario);
  return source;
}

void SceneSource::requireSnapshot(int year) const {
  if (run) requireSnapshotYear(*run, year);
}

void SceneSource::buildLibrary(const LibrarySettings& settings) {
  if (scenario.species.empty()) return;
  library = std::make_unique<TreeLibrary>(loadLibrarySpecies(scenario), settings);
}

}  // namespace eco
