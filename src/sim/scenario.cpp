#include "sim/scenario.hpp"

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
  if (terrain.has("height_range_m")) {
    auto range = terrain.numbers("height_range_m", 2, {}, {-12000.0, 12000.0});
    if (!(range[1] > range[0]))
      terrain.fail("height_range_m", "expected [lowest, highest] with highest > lowest");
    spec.heightMin_m = range[0];
    spec.heightMax_m = range[1];
  }
  terrain.finish();
  return spec;
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
    sim.maxStemsPerHa = simulation->number("max_stems_per_ha", sim.maxStemsPerHa, {1.0, 1e6});
    sim.maxSeedlingsPerHa =
        simulation->number("max_seedlings_per_ha", sim.maxSeedlingsPerHa, {1.0, 1e6});
    sim.lightDirections =
        static_cast<int>(simulation->integer("light_directions", sim.lightDirections, {4, 256}));
    sim.lightRefreshYears = static_cast<int>(
        simulation->integer("light_refresh_years", sim.lightRefreshYears, {1, 10}));
    simulation->finish();
  }
  for (TomlTable& entry : root.tables("species")) {
    ScenarioSpecies species;
    species.where = entry.where("file");
    species.file = file.parent_path() / entry.string("file");
    species.seedRainPerHaPerYear = entry.number("seed_rain_per_ha_per_year", 0.0, {0.0, 1e6});
    entry.finish();
    s.species.push_back(std::move(species));
  }
  s.output.dir = std::filesystem::path("out") / s.name;
  if (std::optional<TomlTable> output = root.table("output")) {
    if (output->has("dir")) s.output.dir = output->string("dir");
    s.output.snapshotEveryYears = static_cast<int>(
        output->integer("snapshot_every_years", s.output.snapshotEveryYears, {1, 100000}));
    output->finish();
  }
  root.finish();
  return s;
}

}  // namespace eco
