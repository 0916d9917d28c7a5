// A whole `ecoforest run` of a scenario, as the user runs it (outputs and checkpoints
// included), timed: wall time, year-step throughput (plants stepped per second) over the
// run and over its last tenth, the slowest year, and peak memory. Goal on the 2-core
// machine: the 6 km², 150-year valley in under 2 minutes.
// Usage: ecosystem_bench [SCENARIO = scenarios/valley.toml] [YEARS = the scenario's]
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/run/simulation.hpp"

int main(int argc, char** argv) {
  const std::filesystem::path scenario =
      argc > 1 ? std::filesystem::path(argv[1])
               : std::filesystem::path(ECOFOREST_DATA_DIR) / "valley.toml";
  const auto out = std::filesystem::temp_directory_path() / "ecoforest_ecosystem_bench";
  std::filesystem::remove_all(out);

  eco::RunOptions options;
  options.scenarioFile = scenario;
  options.out = out;
  if (argc > 2) options.years = std::atoi(argv[2]);
  std::vector<eco::RunProgress> years;
  options.progress = [&](const eco::RunProgress& p) { years.push_back(p); };
  options.warn = [](const std::string& message) { std::fprintf(stderr, "%s\n", message.c_str()); };

  const auto start = std::chrono::steady_clock::now();
  const eco::RunSummary summary = eco::runSimulation(options);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::filesystem::remove_all(out);
  if (years.empty()) return 1;

  // Plants stepped per second, over a span of years (each year steps the plants alive at
  // its start, which is about the count at the end of the year before).
  auto throughput = [&](std::size_t from, std::size_t to) {
    double plants = 0.0;
    for (std::size_t k = from + 1; k <= to; ++k) plants += static_cast<double>(years[k - 1].plants);
    return plants / (years[to].seconds - years[from].seconds);
  };
  double slowest_s = years[0].seconds;
  for (std::size_t k = 1; k < years.size(); ++k)
    slowest_s = std::max(slowest_s, years[k].seconds - years[k - 1].seconds);
  const std::size_t last = years.size() - 1, tail = std::max<std::size_t>(1, years.size() / 10);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);

  std::printf("%s: %d years, %zu plants at the end\n", scenario.filename().c_str(),
              summary.lastYear, years.back().plants);
  std::printf("  wall time            %8.1f s (conditions %.1f s, simulation %.1f s)\n", wall_s,
              summary.conditionsSeconds, summary.simulationSeconds);
  std::printf("  year-step throughput %8.0f plants/s over the run\n",
              summary.plantYears / summary.simulationSeconds);
  if (last >= tail)
    std::printf("                       %8.0f plants/s over the last %zu years\n",
                throughput(last - tail, last), tail);
  std::printf("  slowest year         %8.2f s\n", slowest_s);
  std::printf("  peak memory          %8.0f MiB\n", usage.ru_maxrss / 1024.0);
  for (const eco::SpeciesCount& c : summary.counts)
    std::printf("  %-8s %9lld plants, %8lld taller than 5 m\n", c.name.c_str(),
                static_cast<long long>(c.alive), static_cast<long long>(c.over5m));
  return 0;
}
