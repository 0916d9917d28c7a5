#include "app/conditions_command.hpp"

#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "app/data_paths.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "sim/conditions/condition_maps.hpp"
#include "sim/conditions/conditions.hpp"

namespace eco {
namespace {

struct ConditionsArguments {
  std::string scenario;
  std::string out;
  std::optional<int> threads;
  bool ignoreMemoryCheck = false;
};

void runConditions(const ConditionsArguments& args) {
  Scenario scenario = loadScenario(resolveScenario(args.scenario));
  std::optional<tbb::global_control> threads;
  if (args.threads) threads.emplace(tbb::global_control::max_allowed_parallelism, *args.threads);
  Terrain terrain = loadTerrain(scenario);
  requireMemoryForConditions(terrain.grid, args.ignoreMemoryCheck);
  const std::filesystem::path folder = args.out.empty()
                                           ? std::filesystem::path("out") / scenario.name
                                           : std::filesystem::path(args.out);

  const bool terminal = Progress::stderrIsTerminal();
  std::unique_ptr<Progress> bar;
  std::string current;
  ConditionsReport report;
  ConditionFields fields = computeConditions(terrain, scenario.climate, SunlightSettings{}, &report,
                                             [&](const char* field, double fraction) {
                                               if (current != field) {
                                                 bar.reset();  // finish the previous line
                                                 current = field;
                                                 bar = std::make_unique<Progress>(field, terminal);
                                               }
                                               bar->update(fraction);
                                             });
  bar.reset();
  writeConditionOutputs(fields, report, scenario, folder);
  std::cout << fmt::format("{}: {} x {} cells ({:.2f} km2) -> {}/maps, {}/conditions.json\n",
                           scenario.name, terrain.grid.width, terrain.grid.height,
                           terrain.grid.area_m2() / 1e6, folder.string(), folder.string());
  for (const auto& [name, ms] : report.fieldMilliseconds)
    std::cout << fmt::format("  {:<10} {:8.1f} ms\n", name, ms);
  std::cout << fmt::format("  sun rays   {:8.1f} M ({:.1f} M rays/s)\n", report.sunRays / 1e6,
                           report.sunRaysPerSecond / 1e6);
}

}  // namespace

void addIgnoreMemoryCheckFlag(CLI::App& command, bool& ignore) {
  command.add_flag("--ignore-memory-check", ignore,
                   "Go ahead where the terrain seems too large for the memory available");
}

void addConditionsCommand(CLI::App& app) {
  auto args = std::make_shared<ConditionsArguments>();
  CLI::App* command = app.add_subcommand(
      "conditions", "Compute a scenario's living conditions and write them as maps");
  command
      ->add_option("scenario", args->scenario,
                   "Scenario name (in scenarios/) or path to a scenario .toml")
      ->required();
  command->add_option("--out", args->out, "Output folder (default: out/<scenario name>)");
  addIgnoreMemoryCheckFlag(*command, args->ignoreMemoryCheck);
  command->add_option("--threads", args->threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  command->callback([args] { runConditions(*args); });
}

void addTerrainCommand(CLI::App& app) {
  auto scenario = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "terrain", "Save a scenario's terrain (heightmap or generated) as a 16-bit heightmap image");
  command->add_option("scenario", *scenario, "Scenario name or path")->required();
  command
      ->add_option("--out", *out,
                   "Image file, e.g. terrain.png (16-bit grey, lowest to highest cell)")
      ->required();
  command->callback([scenario, out] {
    Terrain terrain = loadTerrain(loadScenario(resolveScenario(*scenario)));
    FieldStats s = statsOf(terrain.height_m);
    writeHeightmap16(terrain, *out, s.min, s.max);
    std::cout << fmt::format(
        "{}: {} x {} cells, heights {:.1f} .. {:.1f} m; use height_range_m = [{:.1f}, {:.1f}]\n",
        *out, terrain.grid.width, terrain.grid.height, s.min, s.max, s.min, s.max);
  });
}

}  // namespace eco
