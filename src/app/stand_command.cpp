#include "app/stand_command.hpp"

#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "app/scene_source.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "sim/run/stand_table.hpp"

namespace eco {
namespace {

struct StandArgs {
  std::string run;
  std::optional<int> year;
  double classWidth_cm = 5.0;
  std::string out;
};

void runStand(const StandArgs& args) {
  const std::optional<std::filesystem::path> out =
      args.out.empty() ? std::nullopt : std::optional<std::filesystem::path>(args.out);
  if (out) requireOutputFolder(*out);
  const RunFolder run = openRunArgument(args.run);
  if (run.snapshotYears.empty())
    throw InputError({run.dir, 0, "trees"}, "the run has no tree snapshot yet");
  const StandTable table =
      standTablesOfRun(run, {args.year.value_or(run.snapshotYears.back())}, args.classWidth_cm)[0];
  std::cout << standTableText(table);
  if (!out) return;
  AtomicFile file(*out);
  file.write(standTableCsv(table));
  file.commit();
  std::cout << fmt::format("{}: {} rows of {} classes\n", out->string(), table.rows.size(),
                           table.classCount());
}

}  // namespace

void addStandCommand(CLI::App& app) {
  auto args = std::make_shared<StandArgs>();
  CLI::App* command = app.add_subcommand(
      "stand",
      "Print a run's stand table: its trees of 10 cm and more by diameter class and species");
  command->add_option("run", args->run, "Run folder of `ecoforest run`")->required();
  command->add_option("--year", args->year, "Snapshot year (default: the run's last)");
  command->add_option("--class-width", args->classWidth_cm, "Width of a diameter class, cm")
      ->check(CLI::Range(0.5, 100.0))
      ->capture_default_str();
  command->add_option("--out", args->out,
                      "Also write the table as CSV (a line per species and class)");
  command->callback([args] { runStand(*args); });
}

}  // namespace eco
