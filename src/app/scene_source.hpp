// What `render` and `view` show: a run folder (its terrain, species and snapshots) or a
// scenario (its terrain, and optionally a demo planting of its species).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "render/scene/forest.hpp"
#include "render/scene/seen_forest.hpp"
#include "render/scene/tree_library.hpp"
#include "sim/grid.hpp"
#include "sim/run/run_folder.hpp"
#include "sim/scenario.hpp"
#include "sim/terrain.hpp"

namespace eco {

struct SceneSource {
  std::optional<RunFolder> run;
  Scenario scenario;
  Terrain terrain;
  std::unique_ptr<TreeLibrary> library;  // null when there are no trees to draw

  // The year shown when none is asked for: the run's last snapshot.
  int defaultYear() const;
  // An InputError listing the run's snapshot years unless `year` is one of them.
  void requireSnapshot(int year) const;
  // Builds the trees of the scenario's species (slow: every variant, age class and LOD).
  void buildLibrary(const LibrarySettings& settings = {});
  // The trees of a snapshot year (run) or the demo planting (scenario, `demoTrees` > 0).
  Forest forestOf(int year, std::size_t demoTrees) const;
  // The same trees as a still of `frame` from `camera` at `lod` needs them: a snapshot
  // year's read a batch at a time, keeping only those the still can show (forestSeenFrom),
  // the demo planting whole; with the floor of all of them.
  SeenForest forestSeenFrom(int year, std::size_t demoTrees, const Camera& camera, FrameSize frame,
                            const LodSettings& lod) const;
  // The same trees as the ground preset needs them to place its camera: a snapshot year's
  // near the map's centre (groundCameraMaySee), the demo planting whole.
  Forest forestForGroundCamera(int year, std::size_t demoTrees) const;
  // A map for the terrain overlay: a condition, "suitability_<species>" or "canopy_height"
  // from the run's maps/, or a condition computed for a scenario.
  Field overlay(const std::string& name) const;
};

// InputError at --out unless the folder the file (or frame folder) goes into exists.
void requireOutputFolder(const std::filesystem::path& out);

// The run folder a run-only command names (export, timelapse, compare): an InputError when
// `run` is not a folder, before it could be taken for a scenario name.
RunFolder openRunArgument(const std::string& run);
SceneSource openRunSource(const std::string& run);
// An opened run folder's scene: its scenario and terrain.
SceneSource sceneSourceOf(RunFolder run);

// A directory is a run folder; anything else a scenario name or file (resolveScenario).
// The tree library is left to buildLibrary(), so that bad input fails fast.
SceneSource openSceneSource(const std::string& runOrScenario);

}  // namespace eco
