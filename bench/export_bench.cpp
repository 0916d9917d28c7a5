// Seconds and file size of `ecoforest export` for a grown run, in both instancing modes:
// grows the scenario, then writes its last year as forest.glb with one node per tree and
// with GPU instances (LOD1), from plants of at least MIN_HEIGHT metres.
// Usage: export_bench [SCENARIO = valley] [YEARS = the scenario's] [MIN_HEIGHT = 0]
// Blender's import time of the nodes file is measured with
//   blender -b --factory-startup --python tests/app/tools/blender_import.py -- FILE
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bench_run.hpp"
#include "render/scene/forest_export.hpp"

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  const std::filesystem::path scenario =
      argc > 1 ? std::filesystem::path(argv[1])
               : std::filesystem::path(ECOFOREST_DATA_DIR) / "valley.toml";
  const double minHeight = argc > 3 ? std::atof(argv[3]) : 0.0;
  const eco::RunFolder folder = eco::bench::growRun(
      scenario, "export_bench", argc > 2 ? std::optional<int>(std::atoi(argv[2])) : std::nullopt);
  const std::filesystem::path work = folder.dir.parent_path();
  const int year = folder.snapshotYears.back();
  eco::TreeSnapshot snapshot = eco::readSnapshot(folder, year);
  std::erase_if(snapshot.trees, [&](const eco::TreeRow& t) { return t.height_m < minHeight; });
  const eco::Terrain terrain = eco::loadTerrain(folder.scenario);
  std::vector<eco::LibrarySpecies> species = eco::loadLibrarySpecies(folder.scenario);
  const auto libraryStart = Clock::now();
  const eco::TreeLibrary library(std::move(species), {});
  const eco::Forest forest = eco::forestFromSnapshot(snapshot, library, folder.dir.string());
  const double librarySeconds = std::chrono::duration<double>(Clock::now() - libraryStart).count();
  std::printf(
      "%s, year %d: %zu plants of at least %.1f m; tree library with the forest's "
      "types built in %.1f s\n",
      folder.scenario.name.c_str(), year, snapshot.trees.size(), minHeight, librarySeconds);
  for (eco::Instancing instancing : {eco::Instancing::Nodes, eco::Instancing::Gpu}) {
    const bool nodes = instancing == eco::Instancing::Nodes;
    const auto file = work / (nodes ? "nodes.glb" : "gpu.glb");
    const auto start = Clock::now();
    const eco::ForestGltfSummary s = eco::exportForest(terrain, library, forest, snapshot.trees,
                                                       file, {.instancing = instancing});
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    std::printf("  %-5s %8.1f s  %8.1f MB  %zu trees, %.1f M triangles as drawn\n",
                nodes ? "nodes" : "gpu", seconds, std::filesystem::file_size(file) / 1e6,
                s.instances, (s.treeTriangles + s.terrainTriangles) / 1e6);
  }
  std::printf("files in %s\n", work.string().c_str());
  return 0;
}
