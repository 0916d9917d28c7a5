#include "model/species.hpp"

#include <regex>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_support.hpp"

namespace eco {

TEST(Species, BeechHoldsThePapersNumbers) {
  Species beech = test::loadNamed("beech");
  const StrandParams& p = beech.strand;
  EXPECT_EQ(p.strands, 1000);
  EXPECT_DOUBLE_EQ(p.trunkLength_m, 5.0);
  EXPECT_DOUBLE_EQ(p.kd, 0.01);
  EXPECT_DOUBLE_EQ(p.phyllotaxis_deg, 85.0);
  EXPECT_DOUBLE_EQ(p.kc, 0.3);
  EXPECT_DOUBLE_EQ(p.leafSize_m, 0.2862);
  EXPECT_DOUBLE_EQ(p.leafDensity, 5.0);
  EXPECT_EQ(p.leafDistribution, LeafDistribution::Spiral);
  EXPECT_DOUBLE_EQ(beech.wind.directed_wg, 1.5);
  EXPECT_EQ(beech.wind.direction, glm::dvec3(0, 1, 0));
  EXPECT_DOUBLE_EQ(beech.wind.flexibility, 1.0);
  EXPECT_EQ(p.lod, 0);
  ASSERT_EQ(p.graphs.minLenG.points().size(), 3u);
  EXPECT_DOUBLE_EQ(p.graphs.minLenG.points()[1].x, 7.5);
  EXPECT_DOUBLE_EQ(p.graphs.minLenG.points()[1].y, 0.45);
  EXPECT_DOUBLE_EQ(p.graphs.ksG(15.0), 0.9);
  EXPECT_DOUBLE_EQ(p.graphs.alphaG(3.0), 45.0);
}

TEST(Species, PineHoldsThePapersNumbers) {
  Species pine = test::loadNamed("pine");
  const StrandParams& p = pine.strand;
  EXPECT_EQ(p.strands, 6000);
  EXPECT_DOUBLE_EQ(p.trunkLength_m, 5.47);
  EXPECT_DOUBLE_EQ(p.kd, 0.005);
  EXPECT_DOUBLE_EQ(p.kc, 0.98);
  EXPECT_DOUBLE_EQ(p.leafSize_m, 0.1815);
  EXPECT_DOUBLE_EQ(p.leafDensity, 30.0);
  EXPECT_EQ(p.leafDistribution, LeafDistribution::Stacked);
  auto ksW = p.graphs.ksW.points();
  ASSERT_EQ(ksW.size(), 4u);
  EXPECT_DOUBLE_EQ(ksW[1].x, 42.89);
  EXPECT_DOUBLE_EQ(ksW[2].x, 42.89);  // the vertical step
  EXPECT_DOUBLE_EQ(ksW[2].y, 0.654);
  auto alphaM = p.graphs.alphaMG.points();
  ASSERT_EQ(alphaM.size(), 6u);
  EXPECT_DOUBLE_EQ(alphaM[5].y, -0.8532);
  EXPECT_DOUBLE_EQ(p.graphs.klW.points()[3].y, 0.01896);
  EXPECT_DOUBLE_EQ(p.graphs.alphaG.points()[0].y, 128.8);
}

TEST(Species, IsCalledByItsNameOrACommonNameIgnoringCase) {
  const Species shrub = test::loadNamed("shrub");
  EXPECT_EQ(shrub.commonNames, (std::vector<std::string>{"hazel", "common hazel"}));
  EXPECT_TRUE(shrub.isCalled("shrub"));
  EXPECT_TRUE(shrub.isCalled("Hazel"));
  EXPECT_TRUE(shrub.isCalled("COMMON HAZEL"));
  EXPECT_FALSE(shrub.isCalled("hazelnut"));
  EXPECT_FALSE(test::loadNamed("beech").isCalled("hazel"));
}

TEST(Species, DesignedSpeciesLoad) {
  for (const char* name : {"maple", "shrub"}) {
    Species s = test::loadNamed(name);
    EXPECT_EQ(s.name, name);
    EXPECT_GT(s.strand.strands, 1);
    EXPECT_LT(s.wind.flexibility, 1.0) << "designed species sway in the wind";
  }
}

namespace {

const char* kMinimal = R"(name = "t"
[strand]
strands = 10
trunk_length_m = 1.0
kd = 0.01
phyllotaxis_deg = 85
kc = 0.3
leaf_size_m = 0.1
leaf_density = 2
leaf_distribution = "spiral"
[strand.local]
ks_g = [[0, 0.75]]
ks_w = [[0, 1]]
alpha_g_deg = [[0, 45]]
alpha_w = [[0, 1]]
alpha_m_g_deg = [[0, 0]]
alpha_m_w = [[0, 1]]
max_length_g = [[0, 1]]
max_length_w = [[0, 1]]
kl_g = [[0, 1]]
kl_w = [[0, 1]]
min_length_g = [[0, 1]]
min_length_w = [[0, 1]]
)";

// Loads kMinimal with one line replaced and returns the error's text and line.
std::pair<std::string, int> errorWith(const std::string& from, const std::string& to) {
  std::string text = kMinimal;
  std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  auto file = test::writeTemporary("species_error", text);
  try {
    loadSpecies(file);
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, file.string());
    return {error.what(), error.where().line};
  }
  ADD_FAILURE() << "no error for " << to;
  return {"", 0};
}

}  // namespace

TEST(Species, MinimalFileLoads) {
  auto file = test::writeTemporary("species_ok", kMinimal);
  Species s = loadSpecies(file);
  EXPECT_EQ(s.strand.strands, 10);
  EXPECT_EQ(s.variation.branchAngle, Variation{}.branchAngle);  // defaults where absent
}

TEST(Species, BadInputNamesFileLineAndKey) {
  auto [unknown, unknownLine] = errorWith("kc = 0.3", "kc = 0.3\nkcc = 1");
  EXPECT_EQ(unknownLine, 8);
  EXPECT_NE(unknown.find("strand.kcc: unknown key"), std::string::npos) << unknown;

  auto [type, typeLine] = errorWith("kd = 0.01", "kd = \"thin\"");
  EXPECT_EQ(typeLine, 5);
  EXPECT_NE(type.find("strand.kd: expected a number"), std::string::npos) << type;

  auto [zero, zeroLine] = errorWith("strands = 10", "strands = 0");
  EXPECT_EQ(zeroLine, 3);
  EXPECT_NE(zero.find("strand.strands"), std::string::npos);

  auto [negative, negativeLine] = errorWith("trunk_length_m = 1.0", "trunk_length_m = -2.0");
  EXPECT_EQ(negativeLine, 4);
  EXPECT_NE(negative.find("outside"), std::string::npos);

  auto [unsorted, unsortedLine] =
      errorWith("ks_g = [[0, 0.75]]", "ks_g = [[5, 0.75],\n  [1, 0.8]]");
  EXPECT_EQ(unsortedLine, 13);
  EXPECT_NE(unsorted.find("strand.local.ks_g"), std::string::npos);

  auto [distribution, distributionLine] = errorWith("\"spiral\"", "\"fractal\"");
  EXPECT_EQ(distributionLine, 10);

  auto [missing, missingLine] = errorWith("kl_w = [[0, 1]]\n", "");
  EXPECT_NE(missing.find("kl_w: missing required key"), std::string::npos) << missing;
}

// Values a later command would choke on are refused where they are read.
TEST(Species, NamesAndWindMustBeUsable) {
  for (const char* name : {"\"be,ech\"", "\"\"", "\"sub/beech\""}) {
    auto [error, line] = errorWith("name = \"t\"", std::string("name = ") + name);
    EXPECT_EQ(line, 1) << name;
    EXPECT_NE(error.find("cannot name a species"), std::string::npos) << error;
  }
  auto [wind, windLine] = errorWith("kc = 0.3", "kc = 0.3\nwind_direction = [inf, 0, 0]");
  EXPECT_EQ(windLine, 8);
  EXPECT_NE(wind.find("strand.wind_direction: value inf is not a finite number"), std::string::npos)
      << wind;
}

TEST(Species, MissingFileIsAnInputError) {
  EXPECT_THROW(loadSpecies("/nonexistent/oak.toml"), InputError);
}

}  // namespace eco
