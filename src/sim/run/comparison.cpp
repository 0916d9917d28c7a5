#include "sim/run/comparison.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "core/error.hpp"

namespace eco {
namespace {

constexpr int kDefaultYears[] = {30, 60, 100};

std::vector<std::string> speciesOf(const std::vector<ComparedRun>& runs) {
  std::vector<std::string> names;
  for (const ComparedRun& run : runs)
    for (const std::string& s : run.stats.species)
      if (std::find(names.begin(), names.end(), s) == names.end()) names.push_back(s);
  return names;
}

double shareOf(const StandYear& stand, const std::string& species) {
  const auto found = stand.basalAreaShare.find(species);
  return found == stand.basalAreaShare.end() ? 0.0 : found->second;
}

}  // namespace

const StandYear& ComparedRun::at(int year) const {
  const auto found =
      std::find_if(years.begin(), years.end(), [&](const StandYear& s) { return s.year == year; });
  if (found == years.end())
    throw InputError(
        {dir.string(), 0, "--years"},
        fmt::format("the run {} has no year {} (it has years 1 to {})", name, year, lastYear()));
  return *found;
}

ComparedRun readComparedRun(const std::filesystem::path& dir, std::string name) {
  ComparedRun run;
  run.name = std::move(name);
  run.dir = dir;
  const std::filesystem::path file = RunPaths{dir}.stats();
  run.stats = readStatsCsv(file);
  std::map<int, StandYear> byYear;
  for (const StatsRow& r : run.stats.rows) {
    StandYear& y = byYear[r.year];
    y.year = r.year;
    if (r.species == kAllSpecies)
      y.stand = r;
    else
      y.basalAreaShare[run.stats.species[r.species]] = r.basalArea_m2PerHa;
  }
  if (byYear.empty()) throw InputError({file.string(), 0, ""}, "no year in the file");
  double removed = 0.0;
  std::int64_t planted = 0;
  for (int year = 1; year <= byYear.rbegin()->first; ++year) {
    const auto found = byYear.find(year);
    if (found == byYear.end())
      throw InputError({file.string(), 0, ""}, fmt::format("year {} is missing", year));
    StandYear& y = found->second;
    removed += y.stand.removedVolume_m3PerHa;
    planted += y.stand.planted;
    y.removedVolumeSoFar_m3PerHa = removed;
    y.plantedSoFar = planted;
    for (auto& [species, share] : y.basalAreaShare)
      share = y.stand.basalArea_m2PerHa > 0.0 ? share / y.stand.basalArea_m2PerHa : 0.0;
    run.years.push_back(y);
  }
  return run;
}

std::vector<int> comparisonYears(const std::vector<ComparedRun>& runs,
                                 const std::vector<int>& asked) {
  int common = runs.front().lastYear();
  for (const ComparedRun& run : runs) common = std::min(common, run.lastYear());
  if (!asked.empty()) {
    for (int year : asked)
      for (const ComparedRun& run : runs) run.at(year);  // each must reach it
    std::vector<int> years = asked;
    std::sort(years.begin(), years.end());
    years.erase(std::unique(years.begin(), years.end()), years.end());
    return years;
  }
  std::vector<int> years;
  for (int year : kDefaultYears)
    if (year <= common) years.push_back(year);
  if (years.empty()) years.push_back(common);
  return years;
}

std::string comparisonCsv(const std::vector<ComparedRun>& runs, const std::vector<int>& years) {
  const std::vector<std::string> species = speciesOf(runs);
  std::string csv =
      "run,year,basal_area_m2_per_ha,stems_per_ha,mean_height_m,dominant_height_m,"
      "cover_fraction,volume_m3_per_ha,removed_volume_m3_per_ha,planted,plants";
  for (const std::string& s : species) csv += ",share_" + s;
  csv += "\n";
  for (int year : years)
    for (const ComparedRun& run : runs) {
      const StandYear& y = run.at(year);
      const StatsRow& r = y.stand;
      csv += fmt::format("{},{},{:.2f},{:.1f},{:.2f},{:.2f},{:.4f},{:.1f},{:.1f},{},{}", run.name,
                         year, r.basalArea_m2PerHa, r.stemsPerHa, r.meanHeight_m,
                         r.dominantHeight_m, r.coverFraction, r.volume_m3PerHa,
                         y.removedVolumeSoFar_m3PerHa, y.plantedSoFar, r.alive);
      for (const std::string& s : species) csv += fmt::format(",{:.4f}", shareOf(y, s));
      csv += "\n";
    }
  return csv;
}

std::string comparisonMarkdown(const std::vector<ComparedRun>& runs,
                               const std::vector<int>& years) {
  const std::vector<std::string> species = speciesOf(runs);
  std::string md = "# Comparison of " + std::to_string(runs.size()) + " runs\n\n";
  md +=
      "Trees of at least 10 cm dbh; shares are of the basal area; removed volume is by "
      "thinning up to the year.\n";
  for (int year : years) {
    md += fmt::format("\n## Year {}\n\n", year);
    md +=
        "| run | basal area m²/ha | stems/ha | mean height m | dominant height m | cover % | "
        "volume m³/ha | removed m³/ha | planted |";
    for (const std::string& s : species) md += " " + s + " % |";
    md += "\n|---|---:|---:|---:|---:|---:|---:|---:|---:|";
    for (std::size_t k = 0; k < species.size(); ++k) md += "---:|";
    md += "\n";
    for (const ComparedRun& run : runs) {
      const StandYear& y = run.at(year);
      const StatsRow& r = y.stand;
      md += fmt::format(
          "| {} | {:.1f} | {:.0f} | {:.1f} | {:.1f} | {:.0f} | {:.0f} | {:.0f} | {} |", run.name,
          r.basalArea_m2PerHa, r.stemsPerHa, r.meanHeight_m, r.dominantHeight_m,
          100.0 * r.coverFraction, r.volume_m3PerHa, y.removedVolumeSoFar_m3PerHa, y.plantedSoFar);
      for (const std::string& s : species) md += fmt::format(" {:.0f} |", 100.0 * shareOf(y, s));
      md += "\n";
    }
  }
  return md;
}

}  // namespace eco
