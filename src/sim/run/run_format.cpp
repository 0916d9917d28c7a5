#include "sim/run/run_format.hpp"

#include <algorithm>
#include <charconv>
#include <optional>
#include <variant>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/binary_io.hpp"
#include "core/csv_text.hpp"
#include "core/error.hpp"
#include "core/names.hpp"
#include "sim/conditions/conditions.hpp"

namespace eco {
namespace {

constexpr const char* kStatsHeader =
    "year,species,alive,born,died,mean_height_m,stems_per_ha,basal_area_m2_per_ha,qmd_cm,"
    "dominant_height_m,sdi,volume_m3_per_ha,cover_fraction,densest_hectare_basal_area_m2_per_ha,"
    "planted,died_after_planting,removed,removed_volume_m3_per_ha";

std::string fileText(const std::filesystem::path& file) {
  std::optional<std::string> bytes = readFileBytes(file);
  if (!bytes) throw InputError({file.string(), 0, ""}, "cannot read the file");
  return std::move(*bytes);
}

nlohmann::ordered_json siteJson(const std::vector<double>& means) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (std::size_t f = 0; f < means.size(); ++f) json[conditionFieldInfo()[f].name] = means[f];
  return json;
}

}  // namespace

std::filesystem::path RunPaths::snapshot(int year, SnapshotFormat format) const {
  return treesFolder() / fmt::format("year_{:04d}{}", year, extensionOf(format));
}

std::filesystem::path RunPaths::existingSnapshot(int year) const {
  const std::filesystem::path binary = snapshot(year, SnapshotFormat::Binary);
  return std::filesystem::is_regular_file(binary) ? binary : snapshot(year, SnapshotFormat::Csv);
}

std::filesystem::path RunPaths::removed(int year) const {
  return removedFolder() / fmt::format("year_{:04d}.csv", year);
}

std::filesystem::path RunPaths::map(const std::string& name) const {
  return mapsFolder() / (name + ".exr");
}

std::vector<int> RunPaths::snapshotYears() const {
  std::vector<int> years;
  if (std::filesystem::is_directory(treesFolder()))
    for (const auto& entry : std::filesystem::directory_iterator(treesFolder())) {
      const std::string name = entry.path().filename().string();
      int year = 0;
      if (name.size() == 13 && name.starts_with("year_") &&
          snapshotFormatOf(entry.path()).has_value() &&
          parseField(std::string_view(name).substr(5, 4), year))
        years.push_back(year);
    }
  std::sort(years.begin(), years.end());
  years.erase(std::unique(years.begin(), years.end()), years.end());
  return years;
}

std::vector<std::string> RunPaths::mapNames() const {
  std::vector<std::string> names;
  if (std::filesystem::is_directory(mapsFolder()))
    for (const auto& entry : std::filesystem::directory_iterator(mapsFolder()))
      if (entry.path().extension() == ".exr") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

void writeStatsCsv(const std::filesystem::path& file, const std::vector<StatsRow>& rows,
                   const std::vector<EcosystemSpecies>& species) {
  std::string text = std::string(kStatsHeader) + "\n";
  for (const StatsRow& r : rows)
    text += fmt::format(
        "{},{},{},{},{},{:.3f},{:.1f},{:.4f},{:.2f},{:.2f},{:.1f},{:.2f},{:.4f},{:.4f},{},{},{},{:."
        "3f}\n",
        r.year,
        r.species == kAllSpecies ? std::string(kAllSpeciesName) : species[r.species].species.name,
        r.alive, r.born, r.died, r.meanHeight_m, r.stemsPerHa, r.basalArea_m2PerHa, r.qmd_cm,
        r.dominantHeight_m, r.sdi, r.volume_m3PerHa, r.coverFraction,
        r.densestHectareBasalArea_m2PerHa, r.planted, r.diedAfterPlanting, r.removed,
        r.removedVolume_m3PerHa);
  AtomicFile out(file);
  out.write(text);
  out.commit();
}

StatsFile readStatsCsv(const std::filesystem::path& file) {
  using Column =
      std::variant<std::int32_t StatsRow::*, std::int64_t StatsRow::*, double StatsRow::*>;
  struct Known {
    const char* name;
    Column column;
    bool required;
  };
  static const Known kColumns[] = {
      {"year", &StatsRow::year, true},
      {"alive", &StatsRow::alive, true},
      {"born", &StatsRow::born, true},
      {"died", &StatsRow::died, true},
      {"mean_height_m", &StatsRow::meanHeight_m, true},
      {"stems_per_ha", &StatsRow::stemsPerHa, true},
      {"basal_area_m2_per_ha", &StatsRow::basalArea_m2PerHa, true},
      {"qmd_cm", &StatsRow::qmd_cm, true},
      {"dominant_height_m", &StatsRow::dominantHeight_m, true},
      {"sdi", &StatsRow::sdi, true},
      {"volume_m3_per_ha", &StatsRow::volume_m3PerHa, true},
      {"cover_fraction", &StatsRow::coverFraction, true},
      {"densest_hectare_basal_area_m2_per_ha", &StatsRow::densestHectareBasalArea_m2PerHa, true},
      {"planted", &StatsRow::planted, false},
      {"died_after_planting", &StatsRow::diedAfterPlanting, false},
      {"removed", &StatsRow::removed, false},
      {"removed_volume_m3_per_ha", &StatsRow::removedVolume_m3PerHa, false},
  };
  const std::string text = fileText(file);
  StatsFile stats;
  std::vector<std::optional<Column>> columns;  // per field of a line, its column
  std::size_t speciesField = 0;
  std::vector<std::string_view> fields;
  forEachLine(text, [&](int line, std::string_view row) {
    auto fail = [&](const std::string& message) {
      throw InputError({file.string(), line, ""}, message);
    };
    if (line == 1) {
      std::vector<std::string_view> names(64);
      const std::size_t n = splitFields(row, names);
      if (n > names.size()) fail("more than 64 columns: not a stats.csv of ecoforest");
      names.resize(n);
      for (std::size_t f = 0; f < n; ++f) {
        if (names[f] == "species") speciesField = f;
        const auto known = std::find_if(std::begin(kColumns), std::end(kColumns),
                                        [&](const Known& k) { return names[f] == k.name; });
        columns.push_back(known == std::end(kColumns) ? std::nullopt
                                                      : std::optional<Column>(known->column));
      }
      for (const Known& k : kColumns)
        if (k.required && std::find(names.begin(), names.end(), k.name) == names.end())
          fail(fmt::format("no column {}: not a stats.csv of ecoforest", k.name));
      if (std::find(names.begin(), names.end(), "species") == names.end())
        fail("no column species: not a stats.csv of ecoforest");
      fields.resize(n);
      return;
    }
    if (row.empty()) return;
    if (splitFields(row, fields) != fields.size())
      fail(fmt::format("expected {} fields", fields.size()));
    StatsRow r;
    const std::string_view species = fields[speciesField];
    if (species == kAllSpeciesName) {
      r.species = kAllSpecies;
    } else {
      if (const std::string why = whyNotAPlainName(species); !why.empty())
        fail(fmt::format("species '{}' is not a species name: {}", species, why));
      auto found = std::find(stats.species.begin(), stats.species.end(), species);
      if (found == stats.species.end()) found = stats.species.insert(found, std::string(species));
      r.species = static_cast<std::int32_t>(found - stats.species.begin());
    }
    for (std::size_t f = 0; f < fields.size(); ++f) {
      if (!columns[f]) continue;
      std::visit(
          [&](auto member) {
            if (!parseField(fields[f], r.*member) || r.*member < 0)
              fail(fmt::format("field {} ('{}') is not a number of at least 0", f + 1, fields[f]));
          },
          *columns[f]);
    }
    if (r.year < 1) fail(fmt::format("year {} is before year 1", r.year));
    stats.rows.push_back(r);
  });
  if (columns.empty()) throw InputError({file.string(), 0, ""}, "the file is empty");
  return stats;
}

void writeRunJson(const RunPaths& run, const RunRecord& r) {
  nlohmann::ordered_json json;
  json["program"] = "ecoforest";
  json["version"] = r.version;
  json["status"] = r.status;
  if (!r.error.empty()) json["error"] = r.error;
  json["scenario"] = {{"file", std::filesystem::absolute(r.scenarioFile).string()},
                      {"name", r.scenarioName},
                      {"fingerprint", fmt::format("{:016x}", r.fingerprint)},
                      {"text", r.scenarioText}};
  json["seed"] = r.seed;
  json["years"] = r.years;
  json["last_year"] = r.lastYear;
  json["threads"] = r.threads;
  json["timings_s"] = {{"conditions", r.conditionsSeconds},
                       {"simulation", r.simulationSeconds},
                       {"plant_years_per_second", r.plantYearsPerSecond}};
  nlohmann::ordered_json counts = nlohmann::ordered_json::object();
  for (const SpeciesCount& c : r.counts)
    counts[c.name] = {{"alive", c.alive},
                      {"taller_than_5m", c.over5m},
                      {"mean_site_taller_than_5m", siteJson(c.meanSiteOver5m)},
                      {"stems_1_3m_and_taller", c.gaps.stems},
                      {"stems_in_gaps", c.gaps.shares.gaps},
                      {"stems_in_gaps_or_edges", c.gaps.shares.gapsOrEdges}};
  json["final_counts"] = counts;
  json["mean_site_of_map"] = siteJson(r.meanSite);
  json["canopy_gaps"] = {{"map_in_gaps", r.canopyGaps.gaps},
                         {"map_in_gaps_or_edges", r.canopyGaps.gapsOrEdges}};
  AtomicFile out(run.runJson());
  out.write(json.dump(2) + "\n");
  out.commit();
}

RunRecord readRunJson(const RunPaths& run) {
  const std::filesystem::path file = run.runJson();
  if (!std::filesystem::exists(file))
    throw InputError({run.dir.string(), 0, ""},
                     "not a run folder: it has no run.json (make one with `ecoforest run`)");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(fileText(file));
  } catch (const nlohmann::json::exception& e) {
    throw InputError({file.string(), 0, ""}, std::string("not valid JSON: ") + e.what());
  }
  // Written by ecoforest, but read back as untrusted input: every key that is used is
  // checked for its type and range.
  auto fail = [&](const std::string& key, const std::string& what) {
    return InputError({file.string(), 0, key}, what);
  };
  if (!json.is_object() || !json.contains("scenario") || !json["scenario"].is_object())
    throw fail("scenario", "missing: this is not a run.json of ecoforest");
  const nlohmann::json& scenario = json["scenario"];
  auto text = [&](const nlohmann::json& object, const char* key, const std::string& name) {
    if (!object.contains(key)) return std::string();
    if (!object[key].is_string()) throw fail(name, "expected a string");
    return object[key].get<std::string>();
  };
  auto count = [&](const char* key) {
    if (!json.contains(key)) return 0;
    const nlohmann::json& value = json[key];
    if (!value.is_number_integer() || value.get<std::int64_t>() < 0 ||
        value.get<std::int64_t>() > 1000000)
      throw fail(key, "expected a whole number from 0 to 1000000");
    return value.get<int>();
  };
  RunRecord r;
  r.scenarioFile = text(scenario, "file", "scenario.file");
  if (r.scenarioFile.empty()) throw fail("scenario.file", "missing");
  r.version = text(json, "version", "version");
  r.status = text(json, "status", "status");
  if (r.status != "running" && r.status != "complete" && r.status != "interrupted" &&
      r.status != "failed")
    throw fail("status",
               "'" + r.status + "' is not one of running, complete, interrupted and failed");
  r.error = text(json, "error", "error");
  r.scenarioName = text(scenario, "name", "scenario.name");
  r.scenarioText = text(scenario, "text", "scenario.text");
  const std::string hex = text(scenario, "fingerprint", "scenario.fingerprint");
  if (!hex.empty()) {
    const auto [end, error] =
        std::from_chars(hex.data(), hex.data() + hex.size(), r.fingerprint, 16);
    if (error != std::errc() || end != hex.data() + hex.size())
      throw fail("scenario.fingerprint", "expected 16 hexadecimal digits");
  }
  if (json.contains("seed")) {
    if (!json["seed"].is_number_unsigned()) throw fail("seed", "expected a whole number");
    r.seed = json["seed"].get<std::uint64_t>();
  }
  r.years = count("years");
  r.lastYear = count("last_year");
  r.threads = count("threads");
  return r;
}

}  // namespace eco
