#include "app/lsystem_command.hpp"

#include <chrono>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/data_paths.hpp"
#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "model/export/tree_export.hpp"
#include "model/lsystem/deriver.hpp"
#include "model/lsystem/parser.hpp"
#include "model/lsystem/turtle.hpp"
#include "model/mesh/lod.hpp"
#include "model/tree_generator.hpp"

namespace eco {
namespace {

struct LSystemArguments {
  std::string file;
  std::optional<int> iterations;
  std::uint64_t seed = 1;
  std::optional<std::size_t> maxModules;
  bool print = false;
  bool stats = false;
  std::string out;
  int lod = 0;
};

void runLSystem(const LSystemArguments& args) {
  const std::filesystem::path path = resolveLSystem(args.file);
  if (!std::filesystem::is_regular_file(path))
    throw InputError({path.string(), 0, ""}, "no such grammar file");
  auto grammar = std::make_shared<LSystem>(loadLSystem(path));
  if (!args.out.empty()) checkTreeExportPath(args.out);

  DeriveOptions options;
  options.iterations = args.iterations;
  options.seed = args.seed;
  options.maxModules = args.maxModules;
  DeriveStats derived;
  auto start = std::chrono::steady_clock::now();
  const ModuleString string = derive(*grammar, options, &derived);
  const double deriveMs = millisecondsSince(start);
  if (args.print) {
    std::cout << toString(string) << "\n";
    return;
  }

  start = std::chrono::steady_clock::now();
  InterpretStats interpreted;
  TreeSkeleton skeleton = interpretTree(*grammar, string, &interpreted);
  scaleSkeleton(skeleton, static_cast<float>(grammar->turtle.unit_m));
  const double interpretMs = millisecondsSince(start);

  Species species;
  species.name = grammar->name.empty() ? path.stem().string() : grammar->name;
  species.file = path;
  species.generator = TreeGenerator::LSystem;
  species.lsystem.grammarFile = path;
  species.lsystem.grammar = grammar;
  species.lsystem.unit_m = grammar->turtle.unit_m;
  if (!args.out.empty() && !skeleton.segments.empty())
    exportTree(buildLod(skeleton, species, args.lod), species, args.out);
  else if (!args.out.empty())
    throw InputError({path.string(), 0, ""},
                     "the derived string draws nothing (no F): no mesh "
                     "to write");

  const SkeletonMeasures m = measure(skeleton);
  if (args.stats) {
    nlohmann::ordered_json json{
        {"file", path.string()},
        {"seed", args.seed},
        {"iterations", derived.steps},
        {"modules", string.size()},
        {"modules_rewritten", derived.modulesRewritten},
        {"modules_produced", derived.modulesProduced},
        {"segments", interpreted.segments},
        {"leaves", interpreted.leaves},
        {"dropped_leaves", interpreted.droppedLeaves},
        {"height_m", m.height_m},
        {"crown_radius_m", m.crownRadius_m},
        {"derivation_ms", deriveMs},
        {"interpretation_ms", interpretMs},
    };
    std::cout << json.dump(2) << "\n";
  } else if (args.out.empty()) {
    std::cout << species.name << " (seed " << args.seed << ", " << derived.steps
              << " steps): " << string.size() << " modules, " << interpreted.segments
              << " segments, " << interpreted.leaves << " leaves, " << m.height_m << " m tall\n";
  }
}

}  // namespace

void addLSystemCommand(CLI::App& app) {
  auto args = std::make_shared<LSystemArguments>();
  CLI::App* command = app.add_subcommand(
      "lsystem", "Derive an RL-system grammar; print the string, its measures, or export the tree");
  command
      ->add_option("file", args->file,
                   "Grammar file (.lsys) or the name of one in scenarios/lsystems (abop_1_24a)")
      ->required();
  command
      ->add_option("--iterations", args->iterations,
                   "Derivation steps (MaxIt); default: the file's ITERATIONS")
      ->check(CLI::Range(0, kMaxIterations));
  command->add_option("--seed", args->seed, "Random variables' seed: one individual per seed")
      ->capture_default_str();
  command
      ->add_option("--max-modules", args->maxModules,
                   "Cap on the string's length; default: the file's MAXMODULES or 50000000")
      ->check(CLI::Range(std::size_t{1}, std::size_t{2'000'000'000}));
  auto* print = command->add_flag("--print", args->print,
                                  "Write the derived string to stdout (nothing else on stdout)");
  auto* stats = command->add_flag("--stats", args->stats,
                                  "Print modules, segments, leaves and timings as one JSON object");
  print->excludes(stats);
  command->add_option("--out", args->out,
                      "Write the tree mesh: .obj (+.mtl), .gltf, .glb, .pov or .wrl");
  command->add_option("--lod", args->lod, "Level of detail of the written mesh (0, 1, 2)")
      ->check(CLI::Range(0, kLodCount - 1))
      ->capture_default_str();
  command->callback([args] { runLSystem(*args); });
}

}  // namespace eco
