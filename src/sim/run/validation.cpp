#include "sim/run/validation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/binary_io.hpp"
#include "core/csv_text.hpp"
#include "core/error.hpp"
#include "sim/terrain.hpp"

namespace eco {
namespace {

constexpr const char* kYieldTableHeader = "age,stems_per_ha,basal_area_m2_per_ha,qmd_cm";
// Yield tables end at 120-200 years; a few times that leaves room for any.
constexpr int kOldestTableAge = 1000;

double parseNumber(std::string_view text, const SourceLocation& where) {
  double value = 0.0;
  if (!parseField(text, value) || !std::isfinite(value) || value <= 0.0)
    throw InputError(where, fmt::format("expected a positive number, got '{}'", text));
  return value;
}

double relativeError(double simulated, double table) {
  return table > 0.0 ? simulated / table - 1.0 : 0.0;
}

}  // namespace

std::vector<YieldTableRow> readYieldTable(const std::filesystem::path& file) {
  const std::optional<std::string> text = readFileBytes(file);
  if (!text) throw InputError({file.string()}, "cannot read the yield table");
  std::vector<YieldTableRow> rows;
  bool header = false;
  forEachLine(*text, [&](int lineNumber, std::string_view line) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line.front() == '#') return;
    const SourceLocation where{file.string(), lineNumber};
    if (!header) {
      if (line != kYieldTableHeader)
        throw InputError(where, fmt::format("expected the header {}", kYieldTableHeader));
      header = true;
      return;
    }
    std::string_view fields[4];
    if (splitFields(line, fields) != 4)
      throw InputError(where, "expected 4 comma-separated values");
    YieldTableRow row;
    const double age = parseNumber(fields[0], where);
    // Checked before the conversion: a double beyond int's range does not convert.
    if (age != std::floor(age) || age > kOldestTableAge)
      throw InputError(where,
                       fmt::format("the age must be whole years, at most {}", kOldestTableAge));
    row.age_years = static_cast<int>(age);
    row.stemsPerHa = parseNumber(fields[1], where);
    row.basalArea_m2PerHa = parseNumber(fields[2], where);
    row.qmd_cm = parseNumber(fields[3], where);
    if (!rows.empty() && row.age_years <= rows.back().age_years)
      throw InputError(where, "ages must ascend");
    rows.push_back(row);
  });
  if (rows.empty()) throw InputError({file.string()}, "the yield table has no rows");
  return rows;
}

double ValidationAge::stemsError() const {
  return relativeError(simulated.stemsPerHa, table.stemsPerHa);
}
double ValidationAge::basalAreaError() const {
  return relativeError(simulated.basalArea_m2PerHa, table.basalArea_m2PerHa);
}
double ValidationAge::qmdError() const {
  return relativeError(simulated.qmd_cm, table.qmd_cm);
}
double ValidationAge::worstError() const {
  return std::max({std::abs(stemsError()), std::abs(basalAreaError()), std::abs(qmdError())});
}

bool ValidationReport::agesPassed() const {
  return std::all_of(ages.begin(), ages.end(), [&](const ValidationAge& a) {
    return !a.checked || a.worstError() <= settings.tolerance;
  });
}

bool ValidationReport::slopePassed() const {
  return simulatedSlope >= settings.steepestThinningSlope &&
         simulatedSlope <= settings.shallowestThinningSlope;
}

double selfThinningSlope(const std::vector<StandMeasures>& stands) {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (const StandMeasures& m : stands) {
    if (m.stemsPerHa <= 0.0 || m.qmd_cm <= 0.0) continue;
    const double x = std::log(m.qmd_cm), y = std::log(m.stemsPerHa);
    n += 1.0, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double spread = n * sxx - sx * sx;
  if (n < 2.0 || spread <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / spread;
}

ValidationReport validateRun(const RunFolder& run) {
  const Scenario& scenario = run.scenario;
  if (!scenario.validation)
    throw InputError({scenario.file.string()},
                     "the scenario has no [validation] table (docs/validation.md)");
  ValidationReport report;
  report.settings = *scenario.validation;
  const ValidationSettings& v = report.settings;
  const std::vector<YieldTableRow> table = readYieldTable(v.yieldTable);
  for (int age : v.checkedAges)
    if (std::none_of(table.begin(), table.end(),
                     [&](const YieldTableRow& row) { return row.age_years == age; }))
      throw InputError(
          v.where, fmt::format("checked age {} is not an age of {}", age, v.yieldTable.string()));
  const double area_ha = loadTerrain(scenario).grid.area_m2() / 1e4;

  // The planted cohort in a snapshot: the species' trees as old as the run.
  auto cohortOf = [&](int year) {
    const TreeSnapshot snapshot =
        readSnapshot(run, year, [&](const TreeRow& tree) { return tree.age_years == year; });
    const auto named =
        std::find(snapshot.speciesNames.begin(), snapshot.speciesNames.end(), v.species);
    StandTally tally;
    if (named != snapshot.speciesNames.end()) {
      const int species = static_cast<int>(named - snapshot.speciesNames.begin());
      for (const TreeRow& tree : snapshot.trees)
        if (tree.species == species && tree.age_years == year)
          tally.add(tree.dbh_m, tree.height_m, 0.0);
    }
    return tally.perHectare(area_ha);
  };
  auto hasSnapshot = [&](int year) {
    return std::binary_search(run.snapshotYears.begin(), run.snapshotYears.end(), year);
  };
  std::vector<StandMeasures> thinning, tableThinning;
  for (const YieldTableRow& row : table) {
    const bool checked =
        v.checkedAges.empty() ||
        std::find(v.checkedAges.begin(), v.checkedAges.end(), row.age_years) != v.checkedAges.end();
    const bool inThinning =
        row.age_years >= v.thinningFrom_years && row.age_years <= v.thinningTo_years;
    if (inThinning) {
      StandMeasures published;
      published.stemsPerHa = row.stemsPerHa;
      published.qmd_cm = row.qmd_cm;
      tableThinning.push_back(published);
    }
    if (!hasSnapshot(row.age_years)) {
      if (checked && !v.checkedAges.empty()) requireSnapshotYear(run, row.age_years);
      continue;
    }
    ValidationAge age{row, cohortOf(row.age_years), checked};
    if (inThinning) thinning.push_back(age.simulated);
    report.ages.push_back(age);
  }
  report.simulatedSlope = selfThinningSlope(thinning);
  report.tableSlope = selfThinningSlope(tableThinning);
  return report;
}

}  // namespace eco
