// Species and landscapes for the ecosystem tests: species files written on the fly (the
// EcoMod part of beech.toml with an [ecology] chosen by the test) and uniform conditions.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "sim/conditions/conditions.hpp"
#include "sim/ecology/ecosystem.hpp"
#include "terrain_support.hpp"

namespace eco::test {

// The text of scenarios/species/NAME.toml without its [ecology] tables.
std::string withoutEcology(const std::string& name);

// Life history of a simple test species; tolerance and light response may be added as
// extra TOML lines inside [ecology] (before [ecology.life]).
struct TestEcology {
  std::string ecologyLines;  // e.g. "light_response = [[0, 1]]"
  std::string toleranceLines;
  double maxHeight_m = 30.0;
  int maturityAge_years = 10;
  double fecundityPerM2 = 20.0;
  double germination = 0.5;
  double dispersalMean_m = 20.0;
  std::string dispersal = "animal";
};

// Writes a species file named NAME in a fresh folder and loads it with its ecology.
EcosystemSpecies testSpecies(const std::string& name, const TestEcology& ecology);
// scenarios/species/NAME.toml with its ecology.
EcosystemSpecies shippedSpecies(const std::string& name);

// Conditions that every default tolerance finds ideal, on the terrain's grid.
ConditionFields uniformConditions(const Terrain& terrain);

EcosystemSpecies inEcosystem(EcosystemSpecies species, const ConditionFields& fields,
                             double seedRainPerHaPerYear = 0.0);

// A flat hectare (10 x 10 cells of 10 m) with one test species "t" and no plants yet.
struct OneHectare : ::testing::Test {
  Terrain terrain = analyticTerrain(10, 10, 10.0, 10.0, [](double, double) { return 50.0; });
  ConditionFields fields = uniformConditions(terrain);
  Ecosystem ecosystem{
      terrain, fields, {inEcosystem(testSpecies("t", {}), fields)}, EcosystemSettings{}};
};

}  // namespace eco::test
