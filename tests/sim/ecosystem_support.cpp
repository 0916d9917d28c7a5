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
ellenberg = {{ light = 3, temperature = "x", moisture = "x" }}
wind_firmness = 160.0
{}
[ecology.tolerance]
{}
[ecology.life]
max_age_years = 300
max_height_m = {}
height_growth_rate = 0.03
height_growth_shape = 1.4
form_factor = 0.45
foliage_biomass = [0.021708, 1.7]
stem_biomass = [0.22225, 2.2503739]
branch_biomass = [0.022, 2.3]
coarse_root_biomass = [0.018, 2.32]
specific_leaf_area_m2_per_kg = 11.0
leaf_turnover_per_year = 1.0
fine_root_foliage_ratio = 0.75
fine_root_turnover_per_year = 1.0
crown_diameter_silva = [0.5856485, 0.4298499, -0.003455, -0.3238132]
crown_ratio = 0.6
light_use_efficiency = 1.5
maturity_age_years = {}
fecundity_per_m2 = {}
germination = {}
dispersal = "{}"
dispersal_mean_m = {}
)",
                                            e.ecologyLines, e.toleranceLines, e.maxHeight_m,
                                            e.maturityAge_years, e.fecundityPerM2, e.germination,
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
  f.moisture.assign(n, 5.0f);  // Ellenberg's F of fresh soil
  f.windiness.assign(n, 0.1f);
  f.sunniness.assign(n, 1.0f);
  return f;
}

EcosystemSpecies inEcosystem(EcosystemSpecies species, const ConditionFields& fields,
                             double seedRainPerHaPerYear) {
  species.suitability =
      siteSuitability(species.ecology.tolerances(Climate{}), fields, SuitabilityRule::Minimum);
  species.seedRainPerHaPerYear = seedRainPerHaPerYear;
  return species;
}

}  // namespace eco::test
