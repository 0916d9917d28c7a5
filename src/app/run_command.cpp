#include "app/run_command.hpp"

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "app/conditions_command.hpp"
#include "app/data_paths.hpp"
#include "app/run_progress.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "sim/run/simulation.hpp"

namespace eco {
namespace {

struct RunArguments {
  std::string scenario = "default";
  std::optional<std::string> out;
  std::optional<int> years;
  std::optional<int> threads;
  bool resume = false;
  bool ignoreMemoryCheck = false;
};

std::atomic<bool> stopRequested{false};

int runScenario(const RunArguments& args) {
  std::optional<tbb::global_control> threads;
  if (args.threads) threads.emplace(tbb::global_control::max_allowed_parallelism, *args.threads);
  RunOptions options;
  options.scenarioFile = resolveScenario(args.scenario);
  if (args.out) options.out = *args.out;
  options.years = args.years;
  options.resume = args.resume;
  options.ignoreMemoryCheck = args.ignoreMemoryCheck;
  options.programVersion = ECOFOREST_VERSION;
  options.stop = &stopRequested;
  reportToTheUser(options);
  // Ctrl-C or a polite kill finishes the current year, whose files are then complete; a
  // second one stops at once, removing the files being written.
  RunSummary summary = [&] {
    GracefulStop graceful(stopRequested);
    return runSimulation(options);
  }();

  if (summary.interrupted) {
    std::cerr << fmt::format(
        "\nstopped after year {} of {}; continue with: ecoforest run {} --resume{}\n",
        summary.lastYear, summary.targetYears, args.scenario,
        args.out ? " --out " + *args.out : std::string());
    return kExitInterrupted;
  }
  std::cout << fmt::format("{}: {} years -> {}\n", options.scenarioFile.stem().string(),
                           summary.lastYear, summary.folder.string());
  for (const SpeciesCount& c : summary.counts)
    std::cout << fmt::format(
        "  {:<10} {:>8} plants, {:>8} taller than 5 m, stems in gaps or at their edges {:.0f} %\n",
        c.name, c.alive, c.over5m, 100.0 * c.gaps.shares.gapsOrEdges);
  std::cout << fmt::format("  canopy gaps and their edges: {:.0f} % of the map\n",
                           100.0 * summary.canopyGaps.gapsOrEdges);
  std::cout << fmt::format(
      "  conditions {:.1f} s, simulation {:.1f} s ({:.0f} plant-years/s)\n",
      summary.conditionsSeconds, summary.simulationSeconds,
      summary.simulationSeconds > 0.0 ? summary.plantYears / summary.simulationSeconds : 0.0);
  return 0;
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto args = std::make_shared<RunArguments>();
  CLI::App* command = app.add_subcommand(
      "run", "Grow a forest: simulate a scenario's afforestation year by year into a run folder");
  command->add_option("scenario", args->scenario,
                      "Scenario name (in scenarios/) or path to a .toml (default: default)");
  command->add_option("--out", args->out, "Run folder (default: the scenario's [output] dir)");
  command->add_option("--years", args->years, "Years to simulate (default: the scenario's)")
      ->check(CLI::Range(1, 100000));
  addIgnoreMemoryCheckFlag(*command, args->ignoreMemoryCheck);
  command->add_option("--threads", args->threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  command->add_flag("--resume", args->resume,
                    "Continue from the run folder's checkpoint.bin to the same final outputs");
  command->callback([args] {
    const int code = runScenario(*args);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace eco
