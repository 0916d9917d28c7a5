#include "sim/run/run_format.hpp"

#include <algorithm>
#include <charconv>
#include <exception>
#include <fstream>
#include <optional>
#include <sstream>
#include <variant>

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
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
constexpr std::size_t kTreesColumns = 16, kTreesColumnsWithoutSite = 12;

std::string fileText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError({file.string(), 0, ""}, "cannot read the file");
  // Read at once into a string of the file's size (a landscape's snapshot is gigabytes);
  // a stream with no size is read as it comes.
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size < 0 || !in) {
    in.clear();
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), size);
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

nlohmann::ordered_json siteJson(const std::vector<double>& means) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (std::size_t f = 0; f < means.size(); ++f) json[conditionFieldInfo()[f].name] = means[f];
  return json;
}

// What makes a parsed row of a trees file unusable (the numbers are finite already), or "".
// No tree is taller than about 120 m or has a crown wider than about 50 m; the limits leave
// room and keep an edited file from making meshes of astronomical size.
std::string treeRowFault(const TreeRow& tree) {
  constexpr float kTallest_m = 200.0f, kWidestCrown_m = 100.0f;
  if (tree.id == 0) return "id 0: ids start at 1";
  if (tree.age_years < 0) return fmt::format("age {} is negative", tree.age_years);
  if (!(tree.height_m >= 0.0f && tree.height_m <= kTallest_m))
    return fmt::format("height {} m is not between 0 and {} m", tree.height_m, kTallest_m);
  if (!(tree.crownRadius_m >= 0.0f && tree.crownRadius_m <= kWidestCrown_m))
    return fmt::format("crown radius {} m is not between 0 and {} m", tree.crownRadius_m,
                       kWidestCrown_m);
  if (!(tree.crownBase_m >= 0.0f && tree.crownBase_m <= tree.height_m))
    return fmt::format("crown base {} m is not between 0 and the height {} m", tree.crownBase_m,
                       tree.height_m);
  if (!(tree.dbh_m >= 0.0f && tree.dbh_m <= 0.05f * kTallest_m))
    return fmt::format("dbh {} m is not between 0 and {} m", tree.dbh_m, 0.05f * kTallest_m);
  if (!(tree.vigor >= 0.0f && tree.vigor <= 1.0f))
    return fmt::format("vigor {} is not between 0 and 1", tree.vigor);
  // Lengths of at most 1, with room for the file's two decimals.
  constexpr float kLongest = 1.01f;
  if (glm::length(tree.site.light) > kLongest)
    return fmt::format("light ({}, {}) is longer than 1", tree.site.light.x, tree.site.light.y);
  if (glm::length(tree.site.wind) > kLongest)
    return fmt::format("wind ({}, {}) is longer than 1", tree.site.wind.x, tree.site.wind.y);
  return {};
}

}  // namespace

std::filesystem::path RunPaths::snapshot(int year) const {
  return treesFolder() / fmt::format("year_{:04d}.csv", year);
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
        "{},{},{},{},{},{:.3f},{:.1f},{:.4f},{:.2f},{:.2f},{:.1f},{:.2f},{:.4f},{:.4f},{},{},{},{:."
        "3f}\n",
        r.year, r.species == kAllSpecies ? std::string("all") : species[r.species].species.name,
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
    if (species == "all") {
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

void writeTreesCsv(const std::filesystem::path& file, const Ecosystem& ecosystem) {
  writeTreesCsv(file, ecosystem, ecosystem.plants());
}

void writeTreesCsv(const std::filesystem::path& file, const Ecosystem& ecosystem, const Plants& p) {
  const std::vector<EcosystemSpecies>& species = ecosystem.species();
  // Formatted in parallel chunks and written in order, a batch of chunks at a time: a
  // landscape's 100 million rows would otherwise be gigabytes of text in memory at once,
  // and so would their sites, which are worked out row by row. While one batch is written
  // out, the next is formatted.
  constexpr std::size_t kRowsPerChunk = 16384, kChunksPerBatch = 64;
  constexpr std::size_t kRowsPerBatch = kRowsPerChunk * kChunksPerBatch;
  auto formatBatch = [&](std::size_t first, std::vector<std::string>& chunks) {
    tbb::parallel_for(std::size_t{0}, kChunksPerBatch, [&](std::size_t c) {
      std::string& text = chunks[c];
      text.clear();
      const std::size_t begin = std::min(p.size(), first + c * kRowsPerChunk);
      const std::size_t end = std::min(p.size(), begin + kRowsPerChunk);
      text.reserve((end - begin) * 120);
      // The numbers one by one (appendFixed): fmt's float formatting was a tenth of a run.
      auto fixed = [&](float value, int decimals) {
        appendFixed(text, value, decimals);
        text += ',';
      };
      for (std::size_t i = begin; i < end; ++i) {
        fmt::format_to(std::back_inserter(text), "{},{},", p.id[i],
                       species[p.species[i]].species.name);
        fixed(p.east_m[i], 3);
        fixed(p.north_m[i], 3);
        fixed(ecosystem.groundOf(p, i), 3);
        fmt::format_to(std::back_inserter(text), "{},", p.age_years[i]);
        fixed(p.height_m[i], 3);
        fixed(p.crownRadius_m[i], 3);
        fixed(p.crownBase_m[i], 3);
        fixed(p.dbh_m[i], 4);
        fixed(p.vigor[i], 3);
        fmt::format_to(std::back_inserter(text), "{},", ecosystem.variantSeedOf(p.id[i]));
        const PlantSite site = ecosystem.siteOf(p, i);
        fixed(site.light.x, 2);
        fixed(site.light.y, 2);
        fixed(site.wind.x, 2);
        appendFixed(text, site.wind.y, 2);
        text += '\n';
      }
    });
  };
  AtomicFile out(file);
  out.write(std::string(kTreesCsvHeader) + "\n");
  std::vector<std::string> ready(kChunksPerBatch), next(kChunksPerBatch);
  formatBatch(0, ready);
  for (std::size_t first = 0; first < p.size(); first += kRowsPerBatch) {
    tbb::task_group formatting;
    if (first + kRowsPerBatch < p.size())
      formatting.run([&] { formatBatch(first + kRowsPerBatch, next); });
    for (const std::string& text : ready) out.write(text);
    formatting.wait();
    std::swap(ready, next);
  }
  out.commit();
}

namespace {

// A row of a trees file with `columns` fields (with or without the site's), its species
// field aside; an InputError names the line of a row that is not one.
std::string_view parseTreeRow(std::string_view row, std::size_t columns,
                              const std::filesystem::path& file, int line, TreeRow& tree) {
  std::string_view fields[kTreesColumns];
  const std::size_t count = splitFields(row, std::span(fields, columns));
  bool ok = count == columns && parseField(fields[0], tree.id) &&
            parseField(fields[2], tree.east_m) && parseField(fields[3], tree.north_m) &&
            parseField(fields[4], tree.ground_m) && parseField(fields[5], tree.age_years) &&
            parseField(fields[6], tree.height_m) && parseField(fields[7], tree.crownRadius_m) &&
            parseField(fields[8], tree.crownBase_m) && parseField(fields[9], tree.dbh_m) &&
            parseField(fields[10], tree.vigor) && parseField(fields[11], tree.variantSeed) &&
            !fields[1].empty();
  if (ok && columns == kTreesColumns)
    ok = parseField(fields[12], tree.site.light.x) && parseField(fields[13], tree.site.light.y) &&
         parseField(fields[14], tree.site.wind.x) && parseField(fields[15], tree.site.wind.y);
  std::uint64_t wideSeed = 0;
  if (!ok && count == columns && !parseField(fields[11], tree.variantSeed) &&
      parseField(fields[11], wideSeed))
    throw InputError({file.string(), line, "variant_seed"},
                     "a seed beyond 32 bits, as earlier builds of ecoforest wrote them: run "
                     "the scenario again");
  if (!ok)
    throw InputError(
        {file.string(), line, ""},
        fmt::format("expected {} comma-separated numbers: {}", columns,
                    columns == kTreesColumns ? kTreesCsvHeader : kTreesCsvHeaderWithoutSite));
  return fields[1];
}

// A stretch of a trees file's rows, whole lines, read on its own: its trees go to their
// lines' places, their species numbered in the stretch's order of first appearance.
struct TreeChunk {
  std::string_view text;
  int firstLine = 0;
  std::size_t firstSlot = 0;  // the place of its first line among the file's rows
  std::size_t lines = 0;
  std::vector<std::string> speciesNames;
  std::exception_ptr fault;  // its first bad row: the file's first in the earliest chunk
};

void readTreeChunk(TreeChunk& chunk, std::size_t columns, const std::filesystem::path& file,
                   std::vector<TreeRow>& trees, std::vector<char>& filled) {
  try {
    forEachLine(chunk.text, [&](int number, std::string_view row) {
      if (row.empty()) return;
      const int line = chunk.firstLine + number - 1;
      const std::size_t slot = chunk.firstSlot + static_cast<std::size_t>(number - 1);
      TreeRow& tree = trees[slot];
      const std::string_view species = parseTreeRow(row, columns, file, line, tree);
      auto known = std::find(chunk.speciesNames.begin(), chunk.speciesNames.end(), species);
      if (known == chunk.speciesNames.end()) {
        if (const std::string why = whyNotAPlainName(species); !why.empty())
          throw InputError({file.string(), line, ""},
                           fmt::format("species '{}' is not a species name: {}", species, why));
        known = chunk.speciesNames.emplace(known, species);
      }
      if (const std::string fault = treeRowFault(tree); !fault.empty())
        throw InputError({file.string(), line, ""}, fault);
      tree.species = static_cast<int>(known - chunk.speciesNames.begin());
      filled[slot] = 1;
    });
  } catch (...) {
    chunk.fault = std::current_exception();
  }
}

}  // namespace

TreeSnapshot readTreesCsv(const std::filesystem::path& file) {
  const std::string text = fileText(file);
  if (text.empty()) throw InputError({file.string(), 0, ""}, "the file is empty");
  const std::size_t headerEnd = std::min(text.find('\n'), text.size());
  const std::string_view header(text.data(), headerEnd);
  std::size_t columns = kTreesColumns;
  if (header == kTreesCsvHeaderWithoutSite)
    columns = kTreesColumnsWithoutSite;
  else if (header != kTreesCsvHeader)
    throw InputError({file.string(), 1, ""},
                     fmt::format("not a trees file: the header must be '{}'", kTreesCsvHeader));

  // The rows, read in stretches of whole lines side by side (a landscape's snapshot holds
  // tens of millions), each tree put at its line's place: the trees, their species' order
  // and the first fault reported are those of reading the lines in order.
  const std::string_view body = std::string_view(text).substr(std::min(text.size(), headerEnd + 1));
  constexpr std::size_t kChunkBytes = std::size_t{1} << 20;
  std::vector<TreeChunk> chunks;
  for (std::size_t start = 0; start < body.size();) {
    std::size_t end = std::min(body.size(), start + kChunkBytes);
    end = std::min(body.size(), body.find('\n', end - 1) + 1);  // npos + 1 is 0
    if (end <= start) end = body.size();
    chunks.emplace_back().text = body.substr(start, end - start);
    start = end;
  }
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
    const std::string_view t = chunks[c].text;
    chunks[c].lines = static_cast<std::size_t>(std::count(t.begin(), t.end(), '\n')) +
                      (t.empty() || t.back() == '\n' ? 0 : 1);
  });
  std::size_t slots = 0;
  for (TreeChunk& chunk : chunks) {
    chunk.firstSlot = slots;
    chunk.firstLine = static_cast<int>(2 + slots);
    slots += chunk.lines;
  }
  std::vector<TreeRow> trees(slots);
  std::vector<char> filled(slots, 0);  // false for the empty lines between rows
  tbb::parallel_for(std::size_t{0}, chunks.size(),
                    [&](std::size_t c) { readTreeChunk(chunks[c], columns, file, trees, filled); });
  for (const TreeChunk& chunk : chunks)
    if (chunk.fault) std::rethrow_exception(chunk.fault);

  // The species in the file's order of first appearance, and the rows without the gaps.
  TreeSnapshot snapshot;
  std::vector<std::vector<int>> speciesOf(chunks.size());
  for (std::size_t c = 0; c < chunks.size(); ++c)
    for (const std::string& name : chunks[c].speciesNames) {
      auto found = std::find(snapshot.speciesNames.begin(), snapshot.speciesNames.end(), name);
      if (found == snapshot.speciesNames.end()) found = snapshot.speciesNames.insert(found, name);
      speciesOf[c].push_back(static_cast<int>(found - snapshot.speciesNames.begin()));
    }
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
    for (std::size_t slot = chunks[c].firstSlot; slot < chunks[c].firstSlot + chunks[c].lines;
         ++slot)
      if (filled[slot]) trees[slot].species = speciesOf[c][trees[slot].species];
  });
  std::size_t kept = 0;
  for (std::size_t slot = 0; slot < slots; ++slot)
    if (filled[slot]) trees[kept++] = trees[slot];
  trees.resize(kept);
  snapshot.trees = std::move(trees);
  return snapshot;
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
