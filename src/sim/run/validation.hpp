// `ecoforest validate` (docs/validation.md): a planted pure stand against a published yield
// table. The planted cohort -- the trees as old as the run, of the [validation] species --
// is measured as a forester calipers it (stems of at least 10 cm, their basal area and
// quadratic mean diameter) at each age of the table the run has a snapshot of, and its
// self-thinning slope (ln stems over ln quadratic mean diameter, Reineke 1933) is fitted
// over the scenario's years.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sim/ecology/stand_measures.hpp"
#include "sim/run/run_folder.hpp"

namespace eco {

struct YieldTableRow {
  int age_years = 0;
  double stemsPerHa = 0.0, basalArea_m2PerHa = 0.0, qmd_cm = 0.0;
};

// A CSV file: '#' comment lines (the source), a header
// age,stems_per_ha,basal_area_m2_per_ha,qmd_cm and one row per age, ages ascending.
// Throws InputError at the file and line at fault.
std::vector<YieldTableRow> readYieldTable(const std::filesystem::path& file);

struct ValidationAge {
  YieldTableRow table;
  StandMeasures simulated;
  bool checked = false;  // one of the ages the acceptance is judged at
  // Relative differences, simulated / table - 1.
  double stemsError() const;
  double basalAreaError() const;
  double qmdError() const;
  double worstError() const;  // the largest of the three, in magnitude
};

struct ValidationReport {
  ValidationSettings settings;
  std::vector<ValidationAge> ages;  // every table age the run has a snapshot of
  double simulatedSlope = 0.0;      // the cohort's self-thinning slope over the years
  double tableSlope = 0.0;          // the table's over the same years
  bool agesPassed() const;          // every checked age within the tolerance
  bool slopePassed() const;
  bool passed() const { return agesPassed() && slopePassed(); }
};

// Least-squares slope of ln stems over ln qmd; NaN for fewer than two stands.
double selfThinningSlope(const std::vector<StandMeasures>& stands);

// Measures a finished run of a scenario with a [validation] table (an InputError names the
// scenario when it has none, or when a checked age has no snapshot).
ValidationReport validateRun(const RunFolder& run);

}  // namespace eco
