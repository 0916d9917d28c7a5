#include "sim/run/run_format.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/csv_text.hpp"
#include "core/error.hpp"
#include "sim/conditions/conditions.hpp"

namespace eco {
namespace {

constexpr const char* kStatsHeader =
    "year,species,alive,born,died,mean_height_m,stems_per_ha,basal_area_m2_per_ha,qmd_cm,"
    "dominant_height_m,sdi,volume_m3_per_ha,cover_fraction,densest_hectare_basal_area_m2_per_ha";
constexpr std::size_t kTreesColumns = 12;

std::string fileText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError({file.string(), 0, ""}, "cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::ordered_json siteJson(const std::vector<double>& means) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (std::size_t f = 0; f < means.size(); ++f) json[conditionFieldInfo()[f].name] = means[f];
  return json;
}

}  // namespace

std::filesystem::path RunPaths::snapshot(int year) const {
  return treesFolder() / fmt::format("year_{:04d}.csv", year);
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
      if (name.size() == 13 && name.starts_with("year_") && name.ends_with(".csv") &&
          parseField(std::string_view(name).substr(5, 4), year))
        years.push_back(year);
    }
  std::sort(years.begin(), years.end());
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
        "{},{},{},{},{},{:.3f},{:.1f},{:.4f},{:.2f},{:.2f},{:.1f},{:.2f},{:.4f},{:.4f}\n", r.year,
        r.species == kAllSpecies ? std::string("all") : species[r.species].species.name, r.alive,
        r.born, r.died, r.meanHeight_m, r.stemsPerHa, r.basalArea_m2PerHa, r.qmd_cm,
        r.dominantHeight_m, r.sdi, r.volume_m3PerHa, r.coverFraction,
        r.densestHectareBasalArea_m2PerHa);
  AtomicFile out(file);
  out.write(text);
  out.commit();
}

void writeTreesCsv(const std::filesystem::path& file, const Ecosystem& ecosystem) {
  const Plants& p = ecosystem.plants();
  // Formatted in parallel chunks, written in order.
  constexpr std::size_t kRowsPerChunk = 16384;
  std::vector<std::string> chunks((p.size() + kRowsPerChunk - 1) / kRowsPerChunk);
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
    std::string& text = chunks[c];
    const std::size_t end = std::min(p.size(), (c + 1) * kRowsPerChunk);
    text.reserve((end - c * kRowsPerChunk) * 96);
    for (std::size_t i = c * kRowsPerChunk; i < end; ++i)
      fmt::format_to(std::back_inserter(text),
                     "{},{},{:.3f},{:.3f},{:.3f},{},{:.3f},{:.3f},{:.3f},{:.4f},{:.3f},{}\n",
                     p.id[i], ecosystem.species()[p.species[i]].species.name, p.east_m[i],
                     p.north_m[i], p.ground_m[i], p.age_years[i], p.height_m[i], p.crownRadius_m[i],
                     p.crownBase_m[i], p.dbh_m[i], p.vigor[i], p.variantSeed[i]);
  });
  AtomicFile out(file);
  out.write(std::string(kTreesCsvHeader) + "\n");
  for (const std::string& text : chunks) out.write(text);
  out.commit();
}

TreeSnapshot readTreesCsv(const std::filesystem::path& file) {
  const std::string text = fileText(file);
  TreeSnapshot snapshot;
  std::unordered_map<std::string, int> speciesIndex;
  int lines = 0;
  forEachLine(text, [&](int line, std::string_view row) {
    lines = line;
    if (line == 1) {
      if (row != kTreesCsvHeader)
        throw InputError({file.string(), 1, ""},
                         fmt::format("not a trees file: the header must be '{}'", kTreesCsvHeader));
      return;
    }
    if (row.empty()) return;
    std::string_view fields[kTreesColumns];
    const std::size_t count = splitFields(row, fields);
    TreeRow tree;
    bool ok = count == kTreesColumns && parseField(fields[0], tree.id) &&
              parseField(fields[2], tree.east_m) && parseField(fields[3], tree.north_m) &&
              parseField(fields[4], tree.ground_m) && parseField(fields[5], tree.age_years) &&
              parseField(fields[6], tree.height_m) && parseField(fields[7], tree.crownRadius_m) &&
              parseField(fields[8], tree.crownBase_m) && parseField(fields[9], tree.dbh_m) &&
              parseField(fields[10], tree.vigor) && parseField(fields[11], tree.variantSeed) &&
              !fields[1].empty();
    std::uint64_t wideSeed = 0;
    if (!ok && count == kTreesColumns && parseField(fields[11], wideSeed))
      throw InputError({file.string(), line, "variant_seed"},
                       "a seed beyond 32 bits, as earlier builds of ecoforest wrote them: run "
                       "the scenario again");
    if (!ok)
      throw InputError(
          {file.string(), line, ""},
          fmt::format("expected {} comma-separated values: {}", kTreesColumns, kTreesCsvHeader));
    auto [it, added] = speciesIndex.try_emplace(std::string(fields[1]),
                                                static_cast<int>(snapshot.speciesNames.size()));
    if (added) snapshot.speciesNames.emplace_back(fields[1]);
    tree.species = it->second;
    snapshot.trees.push_back(tree);
  });
  if (lines == 0) throw InputError({file.string(), 0, ""}, "the file is empty");
  return snapshot;
}

void writeRunJson(const RunPaths& run, const RunRecord& r) {
  nlohmann::ordered_json json;
  json["program"] = "ecoforest";
  json["version"] = r.version;
  json["status"] = r.status;
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
                      {"mean_site_taller_than_5m", siteJson(c.meanSiteOver5m)}};
  json["final_counts"] = counts;
  json["mean_site_of_map"] = siteJson(r.meanSite);
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
  if (!json.contains("scenario") || !json["scenario"].contains("file") ||
      !json["scenario"]["file"].is_string())
    throw InputError({file.string(), 0, "scenario.file"}, "missing");
  RunRecord r;
  r.scenarioFile = json["scenario"]["file"].get<std::string>();
  r.version = json.value("version", "");
  r.status = json.value("status", "");
  r.scenarioName = json["scenario"].value("name", "");
  r.scenarioText = json["scenario"].value("text", "");
  if (json["scenario"].contains("fingerprint") && json["scenario"]["fingerprint"].is_string()) {
    const std::string hex = json["scenario"]["fingerprint"].get<std::string>();
    std::from_chars(hex.data(), hex.data() + hex.size(), r.fingerprint, 16);
  }
  r.seed = json.value("seed", std::uint64_t{0});
  r.years = json.value("years", 0);
  r.lastYear = json.value("last_year", 0);
  r.threads = json.value("threads", 0);
  return r;
}

}  // namespace eco
