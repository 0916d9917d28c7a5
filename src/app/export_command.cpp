#include "app/export_command.hpp"

#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "app/scene_source.hpp"
#include "core/error.hpp"
#include "render/gl/billboards.hpp"
#include "render/gl/gl_context.hpp"
#include "render/scene/forest_export.hpp"
#include "sim/run/trees_geojson.hpp"

namespace eco {
namespace {

struct ExportArgs {
  std::string run;
  std::optional<int> year;
  std::string out;
  std::string lod = "1";
  std::string instancing = "nodes";
  double minHeight_m = 0.0;
  bool wind = false;
  bool billboards = false;
  bool noShaping = false;
  std::size_t maxTriangles = 0;
};

// The plants at least --min-height tall, the others never held (a landscape's saplings are
// most of its plants).
TreeFilter tallEnough(const ExportArgs& args) {
  if (args.minHeight_m <= 0.0) return {};
  return [minHeight_m = args.minHeight_m](const TreeRow& tree) {
    return tree.height_m >= minHeight_m;
  };
}

// The trees as GeoJSON points in the terrain's coordinates (GIS tools), or as the run's
// CSV snapshot (a binary snapshot, docs/run_folder.md, for tools that read CSV): written a
// batch of rows at a time as they are read, so a landscape's tens of millions of plants
// are never held at once.
void exportTreeRows(const ExportArgs& args, const SceneSource& source, int year, bool geojson) {
  const Grid& grid = source.terrain.grid;
  std::optional<TreesGeoJsonWriter> points;
  std::optional<TreesCsvWriter> rows;
  if (geojson)
    points.emplace(args.out, grid, year);
  else
    rows.emplace(args.out);
  std::size_t count = 0;
  readSnapshotInBatches(*source.run, year, tallEnough(args),
                        [&](std::span<const TreeRow> batch, const std::vector<std::string>& names) {
                          if (points) points->write(batch, names);
                          if (rows) rows->write(batch, names);
                          count += batch.size();
                        });
  if (points) {
    points->commit();
    std::cout << fmt::format(
        "{}: year {}, {} trees as points in {}\n", args.out, year, count,
        grid.epsg != 0 ? fmt::format("EPSG:{}", grid.epsg) : std::string("the map's local metres"));
  } else {
    rows->commit();
    std::cout << fmt::format("{}: year {}, {} trees as CSV rows\n", args.out, year, count);
  }
}

void runExport(const ExportArgs& args) {
  const std::filesystem::path out(args.out);
  const bool geojson = out.extension() == ".geojson", csv = out.extension() == ".csv";
  if (out.extension() != ".glb" && out.extension() != ".gltf" && !geojson && !csv)
    throw InputError({args.out, 0, "--out"},
                     "the forest is written as .glb or .gltf, its trees as .geojson or .csv");
  requireOutputFolder(out);
  ForestGltfOptions options;
  options.instancing = args.instancing == "gpu" ? Instancing::Gpu : Instancing::Nodes;
  options.lod = args.lod == "all"         ? kAllLods
                : args.lod == "billboard" ? kBillboardLevel
                                          : std::stoi(args.lod);
  options.billboards = args.billboards;
  options.wind = args.wind;
  options.maxTriangles = args.maxTriangles;
  if (options.lod == kAllLods && options.instancing != Instancing::Gpu)
    throw InputError({"export", 0, "--lod"},
                     "--lod all writes the levels through MSFT_lod, which needs --instancing gpu");
  SceneSource source = openRunSource(args.run);
  const int year = args.year.value_or(source.defaultYear());
  source.requireSnapshot(year);
  if (geojson || csv) return exportTreeRows(args, source, year, geojson);
  source.buildLibrary(LibrarySettings::shaped(!args.noShaping));
  requireBudgetReachable(source.terrain, *source.library, *source.run, year, tallEnough(args),
                         options);
  const TreeSnapshot snapshot = readSnapshot(*source.run, year, tallEnough(args));
  const Forest forest = forestFromSnapshot(snapshot, *source.library, source.run->dir.string());
  // Billboards are pictures of the trees: the renderer bakes them, headless.
  std::optional<Billboards> billboards;
  if (options.billboards || options.lod == kBillboardLevel) {
    HeadlessGl gl;
    billboards = bakeBillboards(*source.library, typesOf(forest));
  }
  const ForestGltfSummary summary =
      exportForest(source.terrain, *source.library, forest, snapshot.trees, out, options,
                   billboards ? &*billboards : nullptr);
  const auto& at = summary.treesAtLevel;
  const std::string levels =
      options.maxTriangles > 0 ? fmt::format("{} at LOD0, {} at LOD1, {} at LOD2, {} as billboards",
                                             at[0], at[1], at[2], at[3])
                               : "LOD " + args.lod;
  std::cout << fmt::format(
      "{}: year {}, {} trees as {} of {} tree types ({}): {} triangles, terrain {}\n", args.out,
      year, summary.instances, options.instancing == Instancing::Gpu ? "GPU instances" : "nodes",
      summary.treeMeshes, levels, summary.treeTriangles + summary.terrainTriangles,
      summary.terrainTriangles);
}

}  // namespace

void addExportCommand(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* command = app.add_subcommand(
      "export",
      "Write a run's forest of one year as glTF: the terrain and every tree, with its CSV row");
  command->add_option("run", args->run, "A run folder of `ecoforest run`")->required();
  command->add_option("--year", args->year, "Snapshot year (default: the run's last)");
  command
      ->add_option("--out", args->out,
                   "forest.glb or forest.gltf (terrain and trees), trees.geojson (the trees "
                   "as points in the terrain's coordinates) or trees.csv (the snapshot's rows, "
                   "of a binary snapshot too)")
      ->required();
  CLI::Option* maxTriangles =
      command
          ->add_option("--max-triangles", args->maxTriangles,
                       "Keep the scene under N triangles: each tree's level by its height, the "
                       "tallest first (instead of --lod)")
          ->check(CLI::PositiveNumber);
  command
      ->add_option(
          "--lod", args->lod,
          "Level of detail of the tree meshes: 0 full, 1 clustered leaves, 2 crown proxies, "
          "billboard (crossed quads with pictures of the tree), all (LOD0 with the others "
          "through MSFT_lod)")
      ->check(CLI::IsMember({"0", "1", "2", "billboard", "all"}))
      ->excludes(maxTriangles);
  command
      ->add_option("--instancing", args->instancing,
                   "nodes: one node per tree sharing its type's mesh (Blender, assimp, every "
                   "importer); gpu: EXT_mesh_gpu_instancing (three.js, Babylon.js, engines)")
      ->check(CLI::IsMember({"nodes", "gpu"}))
      ->capture_default_str();
  command
      ->add_option("--min-height", args->minHeight_m,
                   "Leave out plants lower than this, metres (seedlings and saplings; default 0: "
                   "every living plant)")
      ->check(CLI::Range(0.0, 1000.0));
  command->add_flag("--billboards", args->billboards,
                    "Add the billboard level, baked by the renderer: the last level of --lod all, "
                    "the coarsest of --max-triangles");
  command->add_flag("--wind", args->wind,
                    "Add the wind bases as vertex attributes (_SWAY_SIN, _SWAY_COS, _BEND_EAST, "
                    "_BEND_SOUTH) for an engine's vertex shader");
  command->add_flag("--no-shaping", args->noShaping,
                    "Trees as their species' own, not shaped by light, wind and crowding");
  command->callback([args] { runExport(*args); });
}

}  // namespace eco
