#include "sim/plan/plan_spec.hpp"

#include <gtest/gtest.h>

#include "core/toml_reader.hpp"

namespace eco {
namespace {

Plan planOf(const std::string& text) {
  TomlDocument doc = TomlDocument::parse(text, "plan.toml");
  TomlTable root = doc.root();
  Plan plan = parsePlan(root, "/scenarios");
  root.finish();
  return plan;
}

// The error a plan text gives, as "file:line: key: message".
std::string errorOf(const std::string& text) {
  try {
    planOf(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PlanSpec, ReadsEveryRule) {
  const Plan plan = planOf(R"([[planting]]
species = { beech = 0.7, maple = 0.3 }
polygon = [[0, 0], [100, 0], [100, 80]]
year = 5
layout = "triangular"
spacing_m = 2.5
height_m = 0.5
age_years = 3
survival_check = false
[[planting]]
rows = ["pine", "pine", "beech"]
mask = "rows.png"
layout = "contour"
[[seed_source]]
species = { beech = 0.9, pine = 0.1 }
border_m = 300
cover = 0.7
[[exclusion]]
line = [[0, 50], [200, 50]]
buffer_m = 3
[[thinning]]
method = "from_below"
from_year = 20
every_years = 10
until_year = 60
target_basal_area_m2_per_ha = 28
species = ["pine"]
)");
  ASSERT_EQ(plan.planting.size(), 2u);
  const Planting& mixed = plan.planting[0];
  ASSERT_EQ(mixed.mix.size(), 2u);
  EXPECT_EQ(mixed.mix[0].species, "beech");
  EXPECT_DOUBLE_EQ(mixed.mix[1].share, 0.3);
  EXPECT_EQ(mixed.region.kind, RegionSpec::Kind::Polygon);
  EXPECT_EQ(mixed.region.points.size(), 3u);
  EXPECT_EQ(mixed.year, 5);
  EXPECT_EQ(mixed.layout, PlantingLayout::Triangular);
  // A triangular grid's rows are sqrt(3)/2 spacings apart unless row_spacing_m says otherwise.
  EXPECT_DOUBLE_EQ(mixed.rowSpacing_m, 2.5 * std::sqrt(3.0) / 2.0);
  EXPECT_EQ(mixed.stockAge_years, 3);
  EXPECT_FALSE(mixed.survivalCheck);
  const Planting& rows = plan.planting[1];
  EXPECT_EQ(rows.speciesNames(), (std::vector<std::string>{"pine", "beech"}));
  EXPECT_EQ(rows.rows.size(), 3u);
  EXPECT_EQ(rows.region.mask, std::filesystem::path("/scenarios/rows.png"));
  EXPECT_TRUE(rows.survivalCheck);
  ASSERT_EQ(plan.seedSources.size(), 1u);
  EXPECT_EQ(plan.seedSources[0].region.kind, RegionSpec::Kind::Border);
  EXPECT_DOUBLE_EQ(plan.seedSources[0].region.border_m, 300.0);
  EXPECT_DOUBLE_EQ(plan.seedSources[0].cover, 0.7);
  ASSERT_EQ(plan.exclusions.size(), 1u);
  EXPECT_EQ(plan.exclusions[0].region.kind, RegionSpec::Kind::Line);
  EXPECT_DOUBLE_EQ(plan.exclusions[0].region.buffer_m, 3.0);
  ASSERT_EQ(plan.thinning.size(), 1u);
  const Thinning& t = plan.thinning[0];
  EXPECT_EQ(t.method, ThinningMethod::FromBelow);
  EXPECT_EQ(*t.targetBasalArea_m2PerHa, 28.0);
  EXPECT_FALSE(t.targetStemsPerHa);
  EXPECT_EQ(t.species, std::vector<std::string>{"pine"});
}

// A region on a command line: the keys of a plan's rule, errors at the option's name.
TEST(PlanSpec, ARegionOptionReadsAsARulesRegion) {
  const RegionSpec polygon = parseRegionOption(
      "polygon = [[0, 0], [400, 0], [400, 300]]\nbuffer_m = 5", "--region", "/work");
  EXPECT_EQ(polygon.kind, RegionSpec::Kind::Polygon);
  ASSERT_EQ(polygon.points.size(), 3u);
  EXPECT_EQ(polygon.points[1], glm::dvec2(400.0, 0.0));
  EXPECT_EQ(polygon.buffer_m, 5.0);
  const RegionSpec mask = parseRegionOption("mask = \"block.png\"", "--region", "/work");
  EXPECT_EQ(mask.mask, std::filesystem::path("/work/block.png"));
  for (const char* bad : {"", "colour = 3", "polygon = [[0, 0], [1, 1]]", "polygon = ["}) {
    try {
      parseRegionOption(bad, "--region", "/work");
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "--region") << bad;
    }
  }
}

TEST(PlanSpec, ThinningYearsRepeatUntilTheLastYear) {
  Thinning t;
  t.fromYear = 20;
  t.everyYears = 10;
  t.untilYear = 50;
  std::vector<int> years;
  for (int year = 1; year <= 100; ++year)
    if (t.appliesIn(year)) years.push_back(year);
  EXPECT_EQ(years, (std::vector<int>{20, 30, 40, 50}));
  t.everyYears = 0;  // once
  EXPECT_TRUE(t.appliesIn(20));
  EXPECT_FALSE(t.appliesIn(30));
}

TEST(PlanSpec, BadRulesNameTheirLineAndKey) {
  EXPECT_NE(errorOf("[[planting]]\nspecies = { beech = 0.5, pine = 0.4 }\n")
                .find("plan.toml:2: planting[0].species: the shares sum to 0.9, not 1"),
            std::string::npos);
  EXPECT_NE(errorOf("[[planting]]\nspecies = \"beech\"\nspacing_m = 0\n")
                .find("plan.toml:3: planting[0].spacing_m: value 0 is outside [0.5, 1000]"),
            std::string::npos);
  // Stock is a sapling of the layer below 4 m: heavy nursery stock of 3.99 m is, a 4 m tree
  // is not.
  EXPECT_EQ(planOf("[[planting]]\nspecies = \"beech\"\nheight_m = 3.99\n").planting[0].height_m,
            3.99);
  EXPECT_NE(errorOf("[[planting]]\nspecies = \"beech\"\nheight_m = 4\n")
                .find("plan.toml:3: planting[0].height_m: value 4 is outside [0.05, 3.99]"),
            std::string::npos);
  EXPECT_NE(errorOf("[[planting]]\nspecies = \"beech\"\npolygon = [[0, 0], [5, 5]]\n")
                .find("plan.toml:3: planting[0].polygon: expected at least 3 points"),
            std::string::npos);
  EXPECT_NE(errorOf("[[planting]]\nspecies = \"beech\"\nlayout = \"hexagonal\"\n")
                .find("plan.toml:3: planting[0].layout: unknown layout 'hexagonal'"),
            std::string::npos);
  EXPECT_NE(errorOf("[[planting]]\nspecies = \"beech\"\nlayout = \"random\"\nspacing_m = 2\n"
                    "min_distance_m = 1.9\n")
                .find("plan.toml:5: planting[0].min_distance_m: at most 0.80 of spacing_m"),
            std::string::npos);
  EXPECT_NE(errorOf("[[planting]]\nspecies = \"beech\"\nrows = [\"pine\"]\n").find("not both"),
            std::string::npos);
  EXPECT_NE(errorOf("[[planting]]\nspacing_m = 2\n").find("say what is planted"),
            std::string::npos);
  EXPECT_NE(errorOf("[[exclusion]]\nline = [[0, 0], [9, 9]]\n")
                .find("plan.toml:2: exclusion[0].line: a line needs buffer_m > 0"),
            std::string::npos);
  EXPECT_NE(errorOf("[[exclusion]]\nbuffer_m = 3\n").find("exclusion[0].buffer_m"),
            std::string::npos);
  EXPECT_NE(errorOf("[[seed_source]]\nspecies = \"beech\"\n")
                .find("plan.toml:2: seed_source[0].species: say where the forest is"),
            std::string::npos);
  EXPECT_NE(errorOf("[[thinning]]\nmethod = \"from_below\"\nfrom_year = 10\n")
                .find("plan.toml:2: thinning[0].method: give one target"),
            std::string::npos);
  EXPECT_NE(errorOf("[[thinning]]\nmethod = \"remove_species\"\nfrom_year = 10\n")
                .find("thinning[0].species: name the species to remove"),
            std::string::npos);
  EXPECT_NE(errorOf("[[thinning]]\nmethod = \"from_above\"\nfrom_year = 30\nuntil_year = 20\n"
                    "target_stems_per_ha = 400\n")
                .find("plan.toml:4: thinning[0].until_year: comes before from_year"),
            std::string::npos);
  EXPECT_NE(errorOf("[[thinning]]\nmethod = \"clearcut\"\n").find("unknown method 'clearcut'"),
            std::string::npos);
}

}  // namespace
}  // namespace eco
