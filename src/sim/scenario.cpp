#include "sim/scenario.hpp"

#include <algorithm>

#include "core/toml_reader.hpp"

namespace eco {
namespace {

TerrainSpec parseTerrain(TomlTable& terrain, const std::filesystem::path& scenarioFolder) {
  TerrainSpec spec;
  if (terrain.has("heightmap")) spec.heightmap = scenarioFolder / terrain.string("heightmap");
  if (std::optional<TomlTable> generate = terrain.table("generate")) {
    if (spec.heightmap)
      terrain.fail("generate", "give either heightmap or [terrain.generate], not both");
    GeneratedTerrain g;
    std::string method = generate->string("method", "midpoint");
    if (method != "midpoint")
      generate->fail("method", "unknown method '" + method + "' (expected midpoint)");
    g.size = static_cast<int>(generate->integer("size", g.size, {3, 8193}));
    if (((g.size - 1) & (g.size - 2)) != 0)
      generate->fail("size",
                     "midpoint displacement needs 2^n + 1 cells per side (e.g. 257, 513, 1025)");
    g.roughness = generate->number("roughness", g.roughness, {0.0, 1.0});
    g.relief_m = generate->number("relief_m", g.relief_m, {0.0, 10000.0});
    spec.baseAltitude_m =
        generate->number("base_altitude_m", spec.baseAltitude_m, {-500.0, 9000.0});
    generate->finish();
    spec.generate = g;
  }
  if (!spec.heightmap && !spec.generate)
    terrain.fail("heightmap", "give heightmap = \"FILE\" or a [terrain.generate] table");
  // cell_size_m: one number, or [dx, dy] for non-square cells.
  std::vector<double> cell =
      terrain.isArray("cell_size_m")
          ? terrain.numbers("cell_size_m", 2)
          : std::vector<double>{terrain.number("cell_size_m", spec.cellDx_m)};
  for (double c : cell)
    if (!(c > 0.0) || c > 100000.0)
      terrain.fail("cell_size_m", "cell size must be a positive number of metres");
  spec.cellDx_m = cell.front();
  spec.cellDy_m = cell.back();
  if (terrain.has("cell_size_m")) spec.cellSizeAt = terrain.where("cell_size_m");
  if (terrain.has("height_range_m")) {
    auto range = terrain.numbers("height_range_m", 2, {}, {-12000.0, 12000.0});
    if (!(range[1] > range[0]))
      terrain.fail("height_range_m", "expected [lowest, highest] with highest > lowest");
    spec.heightMin_m = range[0];
    spec.heightMax_m = range[1];
  }
  const std::string depressions = terrain.string("closed_depressions", "drain");
  if (depressions == "drain")
    spec.closedDepressions = ClosedDepressions::Drain;
  else if (depressions == "pond")
    spec.closedDepressions = ClosedDepressions::Pond;
  else
    terrain.fail("closed_depressions",
                 "unknown kind '" + depressions + "' (expected drain or pond)");
  terrain.finish();
  return spec;
}

ValidationSettings parseValidation(TomlTable& table, const std::filesystem::path& scenarioFolder,
                                   const std::vector<Planting>& planting) {
  auto plants = [](const Planting& p, const std::string& species) {
    const std::vector<std::string> names = p.speciesNames();
    return std::find(names.begin(), names.end(), species) != names.end();
  };
  ValidationSettings v;
  v.where = table.where("yield_table");
  v.yieldTable = scenarioFolder / table.string("yield_table");
  v.species = table.string("species");
  // The cohort measured is a planted one.
  if (std::none_of(planting.begin(), planting.end(),
                   [&](const Planting& p) { return plants(p, v.species); }))
    table.fail("species", "'" + v.species +
                              "' is not planted: a [[planting]] of it is the stand "
                              "compared with the yield table");
  for (double age : table.numberList("checked_ages", std::vector<double>{}, {1.0, 10000.0}))
    v.checkedAges.push_back(static_cast<int>(age));
  v.tolerance = table.number("tolerance", v.tolerance, {0.0, 10.0});
  const std::vector<double> years =
      table.numbers("self_thinning_years", 2, std::vector<double>{60.0, 120.0}, {1.0, 10000.0});
  v.thinningFrom_years = static_cast<int>(years[0]);
  v.thinningTo_years = static_cast<int>(years[1]);
  if (v.thinningTo_years <= v.thinningFrom_years)
    table.fail("self_thinning_years", "expected [first, last] with first < last");
  const std::vector<double> slopes =
      table.numbers("self_thinning_slope", 2, std::vector<double>{-2.0, -1.3}, {-10.0, 0.0});
  v.steepestThinningSlope = slopes[0];
  v.shallowestThinningSlope = slopes[1];
  if (v.shallowestThinningSlope <= v.steepestThinningSlope)
    table.fail("self_thinning_slope", "expected [steepest, shallowest], the steepest first");
  table.finish();
  return v;
}

}  // namespace

Scenario loadScenario(const std::filesystem::path& file) {
  TomlDocument document = TomlDocument::load(file);
  TomlTable root = document.root();
  Scenario s;
  s.file = file;
  s.name = root.string("name", file.stem().string());
  s.seed = static_cast<std::uint64_t>(
      root.integer("seed", static_cast<std::int64_t>(s.seed), {0.0, 9.0e18}));
  std::optional<TomlTable> terrain = root.table("terrain");
  if (!terrain) root.fail("terrain", "missing required table [terrain]");
  s.terrain = parseTerrain(*terrain, file.parent_path());
  if (std::optional<TomlTable> climate = root.table("climate")) {
    Climate& c = s.climate;
    c.latitude_deg = climate->number("latitude_deg", c.latitude_deg, {-89.0, 89.0});
    c.prevailingWindFrom_deg =
        climate->number("prevailing_wind_from_deg", c.prevailingWindFrom_deg, {0.0, 360.0});
    c.annualPrecipitation_mm =
        climate->number("annual_precipitation_mm", c.annualPrecipitation_mm, {0.0, 15000.0});
    c.meanAnnualTemperature_c =
        climate->number("mean_annual_temperature_c", c.meanAnnualTemperature_c, {-30.0, 35.0});
    c.temperatureAltitude_m =
        climate->number("temperature_altitude_m", c.temperatureAltitude_m, {-500.0, 9000.0});
    c.lapseRate_K_per_m = climate->number("lapse_rate_k_per_m", c.lapseRate_K_per_m, {0.0, 0.012});
    climate->finish();
  }
  if (std::optional<TomlTable> simulation = root.table("simulation")) {
    SimulationSettings& sim = s.simulation;
    sim.years = static_cast<int>(simulation->integer("years", sim.years, {1, 100000}));
    const std::string rule = simulation->string("suitability", "minimum");
    if (rule == "minimum")
      sim.suitability = SuitabilityRule::Minimum;
    else if (rule == "product")
      sim.suitability = SuitabilityRule::Product;
    else
      simulation->fail("suitability", "unknown rule '" + rule + "' (expected minimum or product)");
    simulation->finish();
  }
  for (TomlTable& entry : root.tables("species")) {
    ScenarioSpecies species;
    species.where = entry.where("file");
    species.file = file.parent_path() / entry.string("file");
    species.seedRainPerHaPerYear = entry.number("seed_rain_per_ha_per_year", 0.0, {0.0, 1e6});
    species.surroundingForestShare = entry.number("surrounding_forest_share", 0.0, {0.0, 1.0});
    entry.finish();
    s.species.push_back(std::move(species));
  }
  s.plan = parsePlan(root, file.parent_path());
  if (std::optional<TomlTable> validation = root.table("validation"))
    s.validation = parseValidation(*validation, file.parent_path(), s.plan.planting);
  s.output.dir = std::filesystem::path("out") / s.name;
  if (std::optional<TomlTable> output = root.table("output")) {
    if (output->has("dir")) s.output.dir = output->string("dir");
    s.output.snapshotEveryYears = static_cast<int>(
        output->integer("snapshot_every_years", s.output.snapshotEveryYears, {1, 100000}));
    s.output.checkpointEveryYears = static_cast<int>(
        output->integer("checkpoint_every_years", s.output.checkpointEveryYears, {1, 100000}));
    const std::string format = output->string("snapshot_format", "csv");
    if (format == "binary")
      s.output.snapshotFormat = SnapshotFormat::Binary;
    else if (format != "csv")
      output->fail("snapshot_format",
                   "unknown snapshot format '" + format + "' (expected csv or binary)");
    output->finish();
  }
  root.finish();
  return s;
}

}  // namespace eco
