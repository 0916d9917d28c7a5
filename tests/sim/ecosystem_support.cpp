#include "ecosystem_support.hpp"

#include <fmt/format.h>

#include "sim/ecology/suitability.hpp"
#include "test_files.hpp"

namespace eco::test {

std::string withoutEcology(const std::string& name) {
  const std::string text =
      readFile(std::filesystem::path(ECOFOREST_DATA_DIR) / "species" / (name + ".toml"));
  return text.substr(0, text.find("\n# Ecology for the ecosystem simulation"));
}

EcosystemSpecies testSpecies(const std::string& name, const TestEcology& e) {
  const std::string text =
      withoutEcology("beech") + fmt::format(R"(
[ecology]
ellenberg = {{ light = 3, temperature = "x", moisture = "x", continentality = "x" }}
{}
[ecology.tolerance]
{}
[ecology.life]
max_age_years = 300
max_height_m = {}
height_growth_rate = 0.03
height_growth_shape = 1.4
max_dbh_m = 1.0
dbh_growth_rate = 0.012
dbh_growth_shape = 1.3
crown_radius_m = [[0, 0.3], [0.1, 1.8], [0.5, 6.0], [1.0, 9.0]]
crown_ratio = 0.6
crown_transmittance = 0.05
maturity_age_years = {}
seeds_per_year = {}
germination = {}
dispersal = "{}"
dispersal_mean_m = {}
)",
                                            e.ecologyLines, e.toleranceLines, e.maxHeight_m,
                                            e.maturityAge_years, e.seedsPerYear, e.germination,
                                            e.dispersal, e.dispersalMean_m);
  const std::filesystem::path folder = freshDirectory("species_" + name);
  const std::filesystem::path file = folder / (name + ".toml");
  writeFile(file, text);
  EcosystemSpecies species = readEcosystemSpecies(file, {file.string()});
  species.species.name = name;
  return species;
}

EcosystemSpecies shippedSpecies(const std::string& name) {
  const std::filesystem::path file =
      std::filesystem::path(ECOFOREST_DATA_DIR) / "species" / (name + ".toml");
  return readEcosystemSpecies(file, {file.string()});
}

ConditionFields uniformConditions(const Terrain& terrain) {
  ConditionFields f;
  f.grid = terrain.grid;
  const std::size_t n = terrain.grid.cellCount();
  f.altitude_m = terrain.height_m;
  f.slope_deg.assign(n, 0.0f);
  f.aspect_deg.assign(n, -1.0f);
  f.moisture.assign(n, 0.5f);
  f.windiness.assign(n, 0.1f);
  f.sunniness.assign(n, 0.8f);
  return f;
}

EcosystemSpecies inEcosystem(EcosystemSpecies species, const ConditionFields& fields,
                             double seedRainPerHaPerYear) {
  species.suitability =
      siteSuitability(species.ecology.tolerance, fields, SuitabilityRule::Minimum);
  species.seedRainPerHaPerYear = seedRainPerHaPerYear;
  return species;
}

}  // namespace eco::test
