// Comparing runs (`ecoforest compare`, docs/planning.md): each run's stand measures at
// chosen years, from its stats.csv, as a table (CSV and Markdown) and as series over the
// years for charts.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "sim/run/run_format.hpp"

namespace eco {

// A run's whole stand in one year (its stats.csv row "all"), with what its plan has done so
// far and each species' share of the basal area.
struct StandYear {
  int year = 0;
  StatsRow stand;                           // its measures count trees of at least 10 cm dbh
  double removedVolumeSoFar_m3PerHa = 0.0;  // removed by thinning up to this year
  std::int64_t plantedSoFar = 0;
  std::map<std::string, double> basalAreaShare;  // per species, of the stand's basal area
};

struct ComparedRun {
  std::string name;  // the scenario's, or the folder's when two runs share one
  std::filesystem::path dir;
  StatsFile stats;
  std::vector<StandYear> years;  // every year of the run, ascending
  int lastYear() const { return years.empty() ? 0 : years.back().year; }
  // The stand in `year`; an InputError when the run does not reach it.
  const StandYear& at(int year) const;
};

// Reads a run's stats.csv into its yearly stand measures (InputErrors name file and line).
ComparedRun readComparedRun(const std::filesystem::path& dir, std::string name);

// The years to compare: those asked for (each must be reached by every run), or by default
// 30, 60 and 100 as far as every run reaches, else the last year they all reach.
std::vector<int> comparisonYears(const std::vector<ComparedRun>& runs,
                                 const std::vector<int>& asked);

// One row per run and year: the measures and each species' share of the basal area.
std::string comparisonCsv(const std::vector<ComparedRun>& runs, const std::vector<int>& years);
// A table per year, the runs as rows, for reading.
std::string comparisonMarkdown(const std::vector<ComparedRun>& runs, const std::vector<int>& years);

}  // namespace eco
