#include "app/stand_command.hpp"

#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "app/scene_source.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "sim/plan/plan_spec.hpp"
#include "sim/run/stand_table.hpp"

namespace eco {
namespace {

struct StandArgs {
  std::string run;
  std::vector<int> years;  // none: the last
  bool allYears = false;
  double classWidth_cm = 5.0;
  std::string region;  // TOML keys of a plan's region
  std::string out;
};

void runStand(const StandArgs& args) {
  const std::optional<std::filesystem::path> out =
      args.out.empty() ? std::nullopt : std::optional<std::filesystem::path>(args.out);
  if (out) requireOutputFolder(*out);
  std::optional<RegionSpec> region;
  if (!args.region.empty())
    region = parseRegionOption(args.region, "--region", std::filesystem::current_path());
  const RunFolder run = openRunArgument(args.run);
  if (run.snapshotYears.empty())
    throw InputError({run.dir, 0, "trees"}, "the run has no tree snapshot yet");
  std::vector<int> years = args.years;
  if (args.allYears) years = run.snapshotYears;
  if (years.empty()) years = {run.snapshotYears.back()};
  const std::vector<StandTable> tables = standTablesOfRun(run, years, args.classWidth_cm, region);
  // A development over the years: each year's table, and in the CSV each year's lines.
  std::size_t lines = 0;
  for (const StandTable& table : tables) {
    std::cout << (&table == &tables.front() ? "" : "\n") << standTableText(table);
    lines += table.rows.size() * table.classCount();
  }
  if (!out) return;
  AtomicFile file(*out);
  file.write(standTableCsv(tables));
  file.commit();
  std::cout << fmt::format("{}: {} lines of {} year{}\n", out->string(), lines, tables.size(),
                           tables.size() == 1 ? "" : "s");
}

}  // namespace

void addStandCommand(CLI::App& app) {
  auto args = std::make_shared<StandArgs>();
  CLI::App* command = app.add_subcommand(
      "stand",
      "Print a run's stand table: its trees of 10 cm and more by diameter class and species");
  command->add_option("run", args->run, "Run folder of `ecoforest run`")->required();
  CLI::Option* year =
      command
          ->add_option("--year", args->years,
                       "Snapshot year, or years as 50,100,150 (default: the run's last)")
          ->delimiter(',');
  command->add_flag("--all-years", args->allYears, "Every snapshot year of the run")
      ->excludes(year);
  command->add_option("--class-width", args->classWidth_cm, "Width of a diameter class, cm")
      ->check(CLI::Range(0.5, 100.0))
      ->capture_default_str();
  command->add_option("--region", args->region,
                      "Only the trees within a region and per hectare of it, given as a plan's "
                      "rule gives it: 'polygon = [[x, y], ...]' in map metres, or a line or "
                      "mask, with buffer_m (docs/planning.md)");
  command->add_option("--out", args->out,
                      "Also write the tables as CSV (a line per year, species and class)");
  command->callback([args] { runStand(*args); });
}

}  // namespace eco
