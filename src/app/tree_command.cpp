#include "app/tree_command.hpp"

#include <chrono>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/data_paths.hpp"
#include "core/frames.hpp"
#include "core/stopwatch.hpp"
#include "model/export/tree_export.hpp"
#include "model/mesh/lod.hpp"
#include "model/tree_generator.hpp"

namespace eco {
namespace {

struct TreeArguments {
  std::string species;
  std::uint64_t seed = 1;
  double age = 1.0;
  double time = 0.0;
  std::optional<int> lod;
  std::string out;
  bool stats = false;
  std::optional<double> windDirected;
  std::optional<double> windUndirected;
  std::optional<double> windFrom_deg;
  int sides = kDefaultMaxSides;
};

void runTree(const TreeArguments& args) {
  using Clock = std::chrono::steady_clock;
  Species species = loadSpecies(resolveSpecies(args.species));
  TreeBuildOptions options;
  options.seed = args.seed;
  options.age = args.age;
  options.windTime = args.time;
  options.windDirected = args.windDirected;
  options.windUndirected = args.windUndirected;
  if (args.windFrom_deg) options.windDirection = worldDownwindOf(*args.windFrom_deg);
  const int lod = args.lod.value_or(species.strand.lod);

  auto start = Clock::now();
  TreeSkeleton skeleton = buildTree(species, options);
  TreeMesh mesh = buildLod(skeleton, species, lod, args.sides);
  double buildMs = millisecondsSince(start);

  if (!args.out.empty()) exportTree(mesh, species, args.out);

  SkeletonMeasures m = measure(skeleton);
  if (args.stats) {
    nlohmann::ordered_json triangles;
    for (int level = 0; level < kLodCount; ++level)
      triangles["lod" + std::to_string(level)] =
          level == lod ? mesh.triangleCount()
                       : buildLod(skeleton, species, level, args.sides).triangleCount();
    const bool strand = species.generator == TreeGenerator::Strand;
    nlohmann::ordered_json json{{"species", species.name},
                                {"generator", strand ? "strand" : "lsystem"},
                                {"seed", args.seed},
                                {"age", args.age},
                                {"strands", strand ? nlohmann::ordered_json(species.strand.strands)
                                                   : nlohmann::ordered_json(nullptr)},
                                {"segments", m.segments},
                                {"terminal_segments", m.terminalSegments},
                                {"leaves", skeleton.leaves.size()},
                                {"max_gravelius", m.maxGravelius},
                                {"max_weibull", m.maxWeibull},
                                {"height_m", m.height_m},
                                {"crown_radius_m", m.crownRadius_m},
                                {"trunk_diameter_m", m.trunkDiameter_m},
                                {"triangles", triangles},
                                {"build_ms", buildMs}};
    std::cout << json.dump(2) << "\n";
  } else if (args.out.empty()) {
    std::cout << species.name << " (seed " << args.seed << ", age " << args.age
              << "): " << m.segments << " segments, " << skeleton.leaves.size() << " leaves, "
              << m.height_m << " m tall, " << mesh.triangleCount() << " triangles at LOD" << lod
              << "\n";
  }
}

}  // namespace

void addTreeCommand(CLI::App& app) {
  auto args = std::make_shared<TreeArguments>();
  CLI::App* tree =
      app.add_subcommand("tree", "Build one tree of a species, print its measures, export it");
  tree->add_option("species", args->species,
                   "Species name (beech, pine, maple, shrub, birch) or path to a species .toml")
      ->required();
  tree->add_option("--seed", args->seed, "Individual: the same seed always gives the same tree")
      ->capture_default_str();
  tree->add_option("--age", args->age, "Age from 0 (seedling) to 1 (mature)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  tree->add_option("--time", args->time, "Wind time t of the sway oscillation, radians")
      ->capture_default_str();
  tree->add_option("--lod", args->lod,
                   "Level of detail: 0 full, 1 reduced, 2 crown proxy (default: species l_LOD)")
      ->check(CLI::Range(0, kLodCount - 1));
  tree->add_option("--out", args->out, "Write the mesh: .obj (+.mtl), .gltf, .glb, .pov or .wrl");
  tree->add_option("--sides", args->sides,
                   "Ring sides of the stem's tube (thinner branches get fewer, at least 3)")
      ->check(CLI::Range(3, 64))
      ->capture_default_str();
  tree->add_flag("--stats", args->stats, "Print measures and timings as one JSON object");
  tree->add_option("--wind-directed", args->windDirected, "Override w_g, directed wind (0-10)")
      ->check(CLI::Range(0.0, 10.0));
  tree->add_option("--wind-undirected", args->windUndirected,
                   "Override w_s, undirected wind (0-10)")
      ->check(CLI::Range(0.0, 10.0));
  tree->add_option("--wind-from", args->windFrom_deg,
                   "Horizontal directed wind from this compass bearing, degrees (0 north, 90 east)")
      ->check(CLI::Range(0.0, 360.0));
  tree->callback([args] { runTree(*args); });
}

}  // namespace eco
