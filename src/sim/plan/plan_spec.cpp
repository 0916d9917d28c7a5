#include "sim/plan/plan_spec.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/toml_reader.hpp"

namespace eco {
namespace {

// Shares that should sum to 1 may be off by rounding in the file (0.33 + 0.33 + 0.34).
constexpr double kShareSumTolerance = 1e-3;
// Dart throwing fills at most about 55 % of the plane with disks (random sequential
// adsorption's jamming limit, 0.547), so a random layout's minimum distance stays below
// sqrt(0.547 * 4 / pi) = 0.83 of the mean spacing; 0.8 leaves room.
constexpr double kLargestMinDistanceShare = 0.8;

std::vector<glm::dvec2> cornersOf(const std::vector<TomlPoint>& points) {
  std::vector<glm::dvec2> corners;
  for (const TomlPoint& p : points) corners.emplace_back(p.x, p.y);
  return corners;
}

// `key = "beech"` (share 1) or `key = { beech = 0.7, maple = 0.3 }` (shares summing to 1).
std::vector<SpeciesShare> parseMix(TomlTable& table, std::string_view key) {
  if (table.isString(key)) return {{table.string(key), 1.0, table.where(key)}};
  std::optional<TomlTable> mix = table.table(key);
  if (!mix) table.fail(key, "expected a species name or a table of species and their shares");
  std::vector<SpeciesShare> shares;
  double sum = 0.0;
  for (const std::string& name : mix->keys()) {
    SpeciesShare share{name, mix->number(name, {}, {0.0, 1.0}), mix->where(name)};
    sum += share.share;
    shares.push_back(std::move(share));
  }
  mix->finish();
  if (shares.empty()) table.fail(key, "name at least one species");
  if (std::abs(sum - 1.0) > kShareSumTolerance)
    table.fail(key, fmt::format("the shares sum to {:.4g}, not 1", sum));
  return shares;
}

PlantingLayout parseLayout(TomlTable& table) {
  const std::string layout = table.string("layout", "square");
  if (layout == "square") return PlantingLayout::Square;
  if (layout == "triangular") return PlantingLayout::Triangular;
  if (layout == "contour") return PlantingLayout::Contour;
  if (layout == "random") return PlantingLayout::Random;
  table.fail("layout",
             "unknown layout '" + layout + "' (expected square, triangular, contour or random)");
}

Planting parsePlanting(TomlTable& table, const std::filesystem::path& folder) {
  Planting p;
  p.where = table.has("species") ? table.where("species")
            : table.has("rows")  ? table.where("rows")
                                 : table.where("");
  if (table.has("species") && table.has("rows"))
    table.fail("rows", "give species (a name or a table of shares) or rows, not both");
  if (!table.has("species") && !table.has("rows"))
    table.fail("species", "say what is planted: species (a name or a table of shares) or rows");
  if (table.has("species")) {
    p.mix = parseMix(table, "species");
  } else {
    for (const std::string& name : table.stringList("rows", {}))
      p.rows.push_back({name, 1.0, table.where("rows")});
    if (p.rows.empty()) table.fail("rows", "name the species of at least one row");
  }
  p.region = parseRegion(table, folder, false, p.where);
  p.year = static_cast<int>(table.integer("year", p.year, {1, 100000}));
  p.layout = parseLayout(table);
  p.spacing_m = table.number("spacing_m", p.spacing_m, {0.5, 1000.0});
  // A triangular grid's rows lie sqrt(3)/2 spacings apart: every tree has six neighbours at
  // one spacing.
  const double rowSpacing =
      p.layout == PlantingLayout::Triangular ? std::sqrt(3.0) / 2.0 * p.spacing_m : p.spacing_m;
  p.rowSpacing_m = table.number("row_spacing_m", rowSpacing, {0.5, 1000.0});
  if (p.layout == PlantingLayout::Random) {
    p.minDistance_m = table.number("min_distance_m", 0.5 * p.spacing_m, {0.0, 1000.0});
    if (p.minDistance_m > kLargestMinDistanceShare * p.spacing_m)
      table.fail("min_distance_m",
                 fmt::format("at most {:.2f} of spacing_m ({:.3g} m): random trees that far "
                             "apart cannot reach the density a {} m spacing asks for",
                             kLargestMinDistanceShare, kLargestMinDistanceShare * p.spacing_m,
                             p.spacing_m));
    if (table.has("row_spacing_m")) table.fail("row_spacing_m", "a random layout has no rows");
  }
  if (!p.rows.empty() && p.layout == PlantingLayout::Random)
    table.fail("rows", "a random layout has no rows: give species shares instead");
  p.height_m = table.number("height_m", p.height_m, {0.05, 3.99});  // the sapling layer
  p.stockAge_years = static_cast<int>(table.integer("age_years", p.stockAge_years, {0, 20}));
  p.survivalCheck = table.boolean("survival_check", p.survivalCheck);
  table.finish();
  return p;
}

SeedSource parseSeedSource(TomlTable& table, const std::filesystem::path& folder) {
  SeedSource s;
  s.where = table.where("species");
  s.mix = parseMix(table, "species");
  s.region = parseRegion(table, folder, true, s.where);
  if (s.region.kind == RegionSpec::Kind::WholeMap)
    table.fail("species", "say where the forest is: polygon, mask or border_m");
  s.cover = table.number("cover", s.cover, {0.0, 1.0});
  table.finish();
  return s;
}

Exclusion parseExclusion(TomlTable& table, const std::filesystem::path& folder) {
  Exclusion e;
  e.where = table.where("");
  e.region = parseRegion(table, folder, false, e.where);
  if (e.region.kind == RegionSpec::Kind::WholeMap)
    table.fail("polygon", "say what is kept open: polygon, line or mask");
  table.finish();
  return e;
}

Thinning parseThinning(TomlTable& table, const std::filesystem::path& folder) {
  Thinning t;
  t.where = table.where("method");
  const std::string method = table.string("method");
  if (method == "from_below")
    t.method = ThinningMethod::FromBelow;
  else if (method == "from_above")
    t.method = ThinningMethod::FromAbove;
  else if (method == "remove_species")
    t.method = ThinningMethod::RemoveSpecies;
  else
    table.fail("method", "unknown method '" + method +
                             "' (expected from_below, from_above or remove_species)");
  t.region = parseRegion(table, folder, false, t.where);
  t.fromYear = static_cast<int>(table.integer("from_year", {}, {1, 100000}));
  t.everyYears = static_cast<int>(table.integer("every_years", 0, {0, 100000}));
  if (table.has("until_year")) {
    t.untilYear = static_cast<int>(table.integer("until_year", {}, {1, 100000}));
    if (*t.untilYear < t.fromYear) table.fail("until_year", "comes before from_year");
  }
  t.species = table.stringList("species", {});
  if (table.has("target_basal_area_m2_per_ha"))
    t.targetBasalArea_m2PerHa = table.number("target_basal_area_m2_per_ha", {}, {0.0, 500.0});
  if (table.has("target_stems_per_ha"))
    t.targetStemsPerHa = table.number("target_stems_per_ha", {}, {0.0, 1e6});
  if (t.method == ThinningMethod::RemoveSpecies) {
    if (t.species.empty()) table.fail("species", "name the species to remove");
    if (t.targetBasalArea_m2PerHa || t.targetStemsPerHa)
      table.fail(t.targetBasalArea_m2PerHa ? "target_basal_area_m2_per_ha" : "target_stems_per_ha",
                 "remove_species removes every tree of its species: it takes no target");
  } else if (t.targetBasalArea_m2PerHa.has_value() == t.targetStemsPerHa.has_value()) {
    table.fail("method", "give one target: target_basal_area_m2_per_ha or target_stems_per_ha");
  }
  table.finish();
  return t;
}

}  // namespace

RegionSpec parseRegion(TomlTable& table, const std::filesystem::path& folder, bool borderAllowed,
                       const SourceLocation& rule) {
  RegionSpec region;
  region.where = rule;
  int shapes = 0;
  if (table.has("polygon")) {
    region.kind = RegionSpec::Kind::Polygon;
    region.where = table.where("polygon");
    region.points = cornersOf(table.points("polygon", 3));
    ++shapes;
  }
  if (table.has("line")) {
    region.kind = RegionSpec::Kind::Line;
    region.where = table.where("line");
    region.points = cornersOf(table.points("line", 2));
    ++shapes;
  }
  if (table.has("mask")) {
    region.kind = RegionSpec::Kind::Mask;
    region.where = table.where("mask");
    region.mask = folder / table.string("mask");
    ++shapes;
  }
  if (borderAllowed && table.has("border_m")) {
    region.kind = RegionSpec::Kind::Border;
    region.where = table.where("border_m");
    region.border_m = table.number("border_m", {}, {1.0, 1e5});
    ++shapes;
  }
  if (shapes > 1)
    table.fail(table.has("mask") ? "mask" : "line",
               borderAllowed ? "give one of polygon, line, mask and border_m, not several"
                             : "give one of polygon, line and mask, not several");
  region.buffer_m = table.number("buffer_m", 0.0, {0.0, 1e5});
  if (region.kind == RegionSpec::Kind::Line && region.buffer_m <= 0.0)
    table.fail("line", "a line needs buffer_m > 0, the half width of the strip along it");
  if (region.kind == RegionSpec::Kind::WholeMap && table.has("buffer_m"))
    table.fail("buffer_m", "a buffer widens a polygon, line or mask; none is given");
  return region;
}

RegionSpec parseRegionOption(std::string_view text, const std::string& option,
                             const std::filesystem::path& folder) {
  const TomlDocument document = TomlDocument::parse(text, option);
  TomlTable table = document.root();
  const RegionSpec region = parseRegion(table, folder, false, SourceLocation(option));
  table.finish();
  if (region.kind == RegionSpec::Kind::WholeMap)
    throw InputError(SourceLocation(option),
                     "give the region as a plan does: polygon = [[x, y], ...], line = [[x, y], "
                     "...] with buffer_m, or mask = \"FILE.png\" (docs/planning.md)");
  return region;
}

std::vector<std::string> Planting::speciesNames() const {
  std::vector<std::string> names;
  for (const std::vector<SpeciesShare>* list : {&mix, &rows})
    for (const SpeciesShare& s : *list)
      if (std::find(names.begin(), names.end(), s.species) == names.end())
        names.push_back(s.species);
  return names;
}

bool Thinning::appliesIn(int year) const {
  if (year < fromYear || (untilYear && year > *untilYear)) return false;
  return everyYears == 0 ? year == fromYear : (year - fromYear) % everyYears == 0;
}

Plan parsePlan(TomlTable& root, const std::filesystem::path& scenarioFolder) {
  Plan plan;
  for (TomlTable& t : root.tables("planting"))
    plan.planting.push_back(parsePlanting(t, scenarioFolder));
  for (TomlTable& t : root.tables("seed_source"))
    plan.seedSources.push_back(parseSeedSource(t, scenarioFolder));
  for (TomlTable& t : root.tables("exclusion"))
    plan.exclusions.push_back(parseExclusion(t, scenarioFolder));
  for (TomlTable& t : root.tables("thinning"))
    plan.thinning.push_back(parseThinning(t, scenarioFolder));
  return plan;
}

}  // namespace eco
