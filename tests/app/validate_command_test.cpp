// Runs `ecoforest validate` as a user would.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "app_support.hpp"

namespace {

using eco::test::CommandResult;
using eco::test::ecoforest;

// A tiny planted beech plot for 20 years, compared with a table of `stems` per hectare at 20.
std::filesystem::path plot(const std::string& name, const std::string& table,
                           bool validation = true) {
  const auto dir = eco::test::freshDirectory(name);
  eco::test::writeFile(dir / "table.csv", table);
  std::string text = fmt::format(R"(name = "{}"
seed = 3
[terrain]
cell_size_m = 5
[terrain.generate]
size = 9
relief_m = 0
base_altitude_m = 400
[simulation]
years = 20
[[species]]
file = "{}/species/beech.toml"
[[planting]]
species = "beech"
spacing_m = 1.0
[output]
dir = "{}"
snapshot_every_years = 10
)",
                                 name, ECOFOREST_DATA_DIR, (dir / "run").string());
  if (validation)
    text +=
        "[validation]\nyield_table = \"table.csv\"\nspecies = \"beech\"\nchecked_ages = [20]\n"
        "self_thinning_years = [10, 20]\n";
  eco::test::writeFile(dir / "plot.toml", text);
  return dir;
}

TEST(ValidateCommand, PrintsTheComparisonAndJudgesIt) {
  // No plot of 20 years has 100,000 stems of 10 cm per hectare: the check fails, with 4.
  const auto dir = plot("app_validate",
                        "age,stems_per_ha,basal_area_m2_per_ha,qmd_cm\n"
                        "10,100000,50,10\n20,100000,50,10\n");
  CommandResult r = ecoforest("validate " + (dir / "plot.toml").string());
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_NE(r.output.find("planted beech against table.csv"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("*    20"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("FAILED"), std::string::npos) << r.output;
  const std::string csv = eco::test::readFile(dir / "run" / "validation.csv");
  EXPECT_EQ(csv.substr(0, csv.find(',')), "age");
  EXPECT_NE(csv.find("\n20,1,"), std::string::npos) << csv;
  // The same comparison of the finished folder, without running again.
  CommandResult again = ecoforest("validate --existing " + (dir / "run").string());
  EXPECT_EQ(again.exitCode, 4);
  EXPECT_EQ(again.output.substr(again.output.find("planted")),
            r.output.substr(r.output.find("planted")));
}

TEST(ValidateCommand, AScenarioWithoutAValidationTableIsBadInput) {
  const auto dir = plot("app_validate_none", "", false);
  CommandResult r = ecoforest("validate " + (dir / "plot.toml").string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("has no [validation] table"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "run"));  // refused before running
}

}  // namespace
