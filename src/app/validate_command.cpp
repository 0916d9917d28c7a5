#include "app/validate_command.hpp"

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "app/data_paths.hpp"
#include "app/run_progress.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "sim/run/simulation.hpp"
#include "sim/run/validation.hpp"

namespace eco {
namespace {

struct ValidateArguments {
  std::string scenario;
  std::optional<std::string> out;
  std::optional<int> threads;
  bool existing = false;
};

std::string percent(double error) {
  return fmt::format("{:+.0f}%", 100.0 * error);
}

std::string slopeText(double slope) {
  return std::isnan(slope) ? std::string("n/a") : fmt::format("{:.2f}", slope);
}

// The comparison as a table for the terminal; checked ages are marked with '*'.
std::string reportText(const ValidationReport& r) {
  const ValidationSettings& v = r.settings;
  std::string text =
      fmt::format("planted {} against {}\n", v.species, v.yieldTable.filename().string());
  text += fmt::format("  {:>5} {:>17} {:>6} {:>18} {:>6} {:>14} {:>6}\n", "age", "stems/ha (table)",
                      "", "m2/ha (table)", "", "qmd cm (table)", "");
  for (const ValidationAge& a : r.ages)
    text += fmt::format(
        "{} {:>5} {:>8.0f} ({:>6.0f}) {:>6} {:>9.1f} ({:>6.1f}) {:>6} {:>6.1f} ({:>5.1f}) {:>6}\n",
        a.checked ? '*' : ' ', a.table.age_years, a.simulated.stemsPerHa, a.table.stemsPerHa,
        percent(a.stemsError()), a.simulated.basalArea_m2PerHa, a.table.basalArea_m2PerHa,
        percent(a.basalAreaError()), a.simulated.qmd_cm, a.table.qmd_cm, percent(a.qmdError()));
  text += fmt::format(
      "self-thinning slope (ln stems / ln qmd), years {}-{}: {} (table {}), "
      "accepted {:.2f} .. {:.2f}\n",
      v.thinningFrom_years, v.thinningTo_years, slopeText(r.simulatedSlope),
      slopeText(r.tableSlope), v.steepestThinningSlope, v.shallowestThinningSlope);
  text += fmt::format("checked ages (*) within {:.0f}%: {}; slope: {}; {}\n", 100.0 * v.tolerance,
                      r.agesPassed() ? "yes" : "no", r.slopePassed() ? "yes" : "no",
                      r.passed() ? "PASSED" : "FAILED");
  return text;
}

std::string reportCsv(const ValidationReport& r) {
  std::string csv =
      "age,checked,stems_per_ha,table_stems_per_ha,basal_area_m2_per_ha,table_basal_area_m2_per_ha,"
      "qmd_cm,table_qmd_cm\n";
  for (const ValidationAge& a : r.ages)
    csv += fmt::format("{},{},{:.1f},{:.1f},{:.2f},{:.2f},{:.2f},{:.2f}\n", a.table.age_years,
                       a.checked ? 1 : 0, a.simulated.stemsPerHa, a.table.stemsPerHa,
                       a.simulated.basalArea_m2PerHa, a.table.basalArea_m2PerHa, a.simulated.qmd_cm,
                       a.table.qmd_cm);
  return csv;
}

int validate(const ValidateArguments& args) {
  std::optional<tbb::global_control> threads;
  if (args.threads) threads.emplace(tbb::global_control::max_allowed_parallelism, *args.threads);
  std::filesystem::path folder;
  if (args.existing) {
    folder = args.scenario;
  } else {
    RunOptions options;
    options.scenarioFile = resolveScenario(args.scenario);
    const Scenario scenario = loadScenario(options.scenarioFile);
    if (!scenario.validation)
      throw InputError(
          {options.scenarioFile.string()},
          "the scenario has no [validation] table to compare with (docs/validation.md)");
    if (args.out) options.out = *args.out;
    options.programVersion = ECOFOREST_VERSION;
    reportToTheUser(options);
    folder = runSimulation(options).folder;
  }
  const ValidationReport report = validateRun(openRunFolder(folder));
  AtomicFile csv(folder / "validation.csv");
  csv.write(reportCsv(report));
  csv.commit();
  std::cout << reportText(report) << "  -> " << (folder / "validation.csv").string() << "\n";
  return report.passed() ? 0 : kExitValidationFailed;
}

}  // namespace

void addValidateCommand(CLI::App& app) {
  auto args = std::make_shared<ValidateArguments>();
  CLI::App* command = app.add_subcommand("validate",
                                         "Run a scenario with a [validation] table and compare its "
                                         "planted stand with the yield table");
  command
      ->add_option(
          "scenario", args->scenario,
          "Scenario name (in scenarios/) or path to a .toml; with --existing, a run folder")
      ->required();
  command->add_option("--out", args->out, "Run folder (default: the scenario's [output] dir)");
  command->add_option("--threads", args->threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  command->add_flag("--existing", args->existing,
                    "Compare a finished run folder instead of running the scenario again");
  command->callback([args] {
    const int code = validate(*args);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace eco
