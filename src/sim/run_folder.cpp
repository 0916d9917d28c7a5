#include "sim/run_folder.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace eco {
namespace {

constexpr const char* kTreesHeader =
    "id,species,x_m,y_m,z_m,age,height_m,crown_radius_m,dbh_m,vigor,variant_seed";

std::string fileText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError({file.string(), 0, ""}, "cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

template <class T>
bool parseField(std::string_view field, T& value) {
  const char* end = field.data() + field.size();
  auto [ptr, ec] = std::from_chars(field.data(), end, value);
  return ec == std::errc() && ptr == end;
}

}  // namespace

RunFolder openRunFolder(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir))
    throw InputError({dir.string(), 0, ""}, "no such run folder");
  const std::filesystem::path jsonFile = dir / "run.json";
  if (!std::filesystem::exists(jsonFile))
    throw InputError({dir.string(), 0, ""},
                     "not a run folder: it has no run.json (make one with `ecoforest run`)");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(fileText(jsonFile));
  } catch (const nlohmann::json::exception& e) {
    throw InputError({jsonFile.string(), 0, ""}, std::string("not valid JSON: ") + e.what());
  }
  if (!json.contains("scenario") || !json["scenario"].contains("file") ||
      !json["scenario"]["file"].is_string())
    throw InputError({jsonFile.string(), 0, "scenario.file"}, "missing");
  RunFolder run;
  run.dir = dir;
  run.scenario = loadScenario(json["scenario"]["file"].get<std::string>());
  if (std::filesystem::is_directory(dir / "trees"))
    for (const auto& entry : std::filesystem::directory_iterator(dir / "trees")) {
      const std::string name = entry.path().filename().string();
      int year = 0;
      if (name.size() == 13 && name.starts_with("year_") && name.ends_with(".csv") &&
          parseField(std::string_view(name).substr(5, 4), year))
        run.snapshotYears.push_back(year);
    }
  std::sort(run.snapshotYears.begin(), run.snapshotYears.end());
  return run;
}

void requireSnapshotYear(const RunFolder& run, int year) {
  if (!std::binary_search(run.snapshotYears.begin(), run.snapshotYears.end(), year)) {
    std::string years;
    for (int y : run.snapshotYears) years += (years.empty() ? "" : ", ") + std::to_string(y);
    throw InputError({run.dir.string(), 0, "year"},
                     fmt::format("the run has no snapshot of year {} (it has: {})", year,
                                 years.empty() ? "none" : years));
  }
}

TreeSnapshot readSnapshot(const RunFolder& run, int year) {
  requireSnapshotYear(run, year);
  TreeSnapshot snapshot = readTreesCsv(run.dir / "trees" / fmt::format("year_{:04d}.csv", year));
  snapshot.year = year;
  return snapshot;
}

TreeSnapshot readTreesCsv(const std::filesystem::path& file) {
  const std::string text = fileText(file);
  TreeSnapshot snapshot;
  std::unordered_map<std::string, int> speciesIndex;
  std::size_t lineStart = 0;
  int line = 0;
  while (lineStart < text.size()) {
    std::size_t lineEnd = text.find('\n', lineStart);
    if (lineEnd == std::string::npos) lineEnd = text.size();
    std::string_view row(text.data() + lineStart, lineEnd - lineStart);
    lineStart = lineEnd + 1;
    ++line;
    if (line == 1) {
      if (row != kTreesHeader)
        throw InputError({file.string(), 1, ""},
                         fmt::format("not a trees file: the header must be '{}'", kTreesHeader));
      continue;
    }
    if (row.empty()) continue;
    std::string_view fields[11];
    int count = 0;
    for (std::size_t start = 0; count < 11;) {
      const std::size_t comma = row.find(',', start);
      fields[count++] = row.substr(
          start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    TreeRow tree;
    bool ok = count == 11 && parseField(fields[0], tree.id) && parseField(fields[2], tree.east_m) &&
              parseField(fields[3], tree.north_m) && parseField(fields[4], tree.ground_m) &&
              parseField(fields[5], tree.age_years) && parseField(fields[6], tree.height_m) &&
              parseField(fields[7], tree.crownRadius_m) && parseField(fields[8], tree.dbh_m) &&
              parseField(fields[9], tree.vigor) && parseField(fields[10], tree.variantSeed) &&
              !fields[1].empty();
    if (!ok)
      throw InputError({file.string(), line, ""},
                       "expected 11 comma-separated values: id,species,x_m,...,variant_seed");
    auto [it, added] = speciesIndex.try_emplace(std::string(fields[1]),
                                                static_cast<int>(snapshot.speciesNames.size()));
    if (added) snapshot.speciesNames.emplace_back(fields[1]);
    tree.species = it->second;
    snapshot.trees.push_back(tree);
  }
  if (line == 0) throw InputError({file.string(), 0, ""}, "the file is empty");
  return snapshot;
}

}  // namespace eco
