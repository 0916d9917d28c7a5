#include "model/species_schema.hpp"

#include <set>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace eco {

TEST(SpeciesSchema, TablesAreInTheEnumsOrderWithUniqueKeys) {
  std::set<std::string_view> keys;
  for (std::size_t i = 0; i < globalParameters().size(); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(globalParameters()[i].parameter), i);
    EXPECT_TRUE(keys.insert(globalParameters()[i].key).second);
  }
  for (std::size_t i = 0; i < localGraphs().size(); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(localGraphs()[i].graph), i);
    EXPECT_TRUE(keys.insert(localGraphs()[i].key).second);
  }
  EXPECT_EQ(globalParameters().size(), static_cast<std::size_t>(kGlobalParameterCount));
  EXPECT_EQ(localGraphs().size(), static_cast<std::size_t>(kLocalGraphCount));
}

TEST(SpeciesSchema, HoldsThePapersBounds) {
  // Section II.A: S 0..5000 on the slider, l_0 0..10 m, k_d 0..0.05, k_c 0..1, alpha_p
  // 0..360, rho_l 0..30, l_l 0..0.3, w_g and w_s 0..10.
  EXPECT_EQ(infoOf(GlobalParameter::Strands).slider.max, 5000);
  EXPECT_EQ(infoOf(GlobalParameter::Kd).slider.max, 0.05);
  EXPECT_EQ(infoOf(GlobalParameter::LeafDensity).slider.max, 30);
  EXPECT_EQ(infoOf(GlobalParameter::LeafSize).slider.max, 0.3);
  EXPECT_EQ(infoOf(GlobalParameter::WindUndirected).slider.max, 10);
  // Section II.B and III.A: k_s^g in [1/2, 1], alpha_m^g in [-180, 180], g over [0, 15], w
  // over [0, 50].
  EXPECT_EQ(infoOf(LocalGraph::KsG).values.min, 0.5);
  EXPECT_EQ(infoOf(LocalGraph::AlphaMG).values.min, -180);
  EXPECT_EQ(infoOf(LocalGraph::MaxLenW).values.max, 2);
  EXPECT_EQ(orderAxis(BranchOrder::Gravelius).max, 15);
  EXPECT_EQ(orderAxis(BranchOrder::Weibull).max, 50);
}

TEST(SpeciesSchema, EveryGraphBelongsToOnePairOverGAndW) {
  std::set<LocalGraph> seen;
  for (const GraphPair& pair : graphPairs()) {
    EXPECT_EQ(infoOf(pair.overG).over, BranchOrder::Gravelius);
    EXPECT_EQ(infoOf(pair.overW).over, BranchOrder::Weibull);
    seen.insert(pair.overG);
    seen.insert(pair.overW);
    EXPECT_EQ(&pairOf(pair.overG), &pair);
  }
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(kLocalGraphCount));
}

TEST(SpeciesSchema, ValuesReadAndWriteTheSpecies) {
  Species beech = test::loadNamed("beech");
  EXPECT_EQ(valueOf(beech, GlobalParameter::Strands), 1000);
  EXPECT_EQ(valueOf(beech, GlobalParameter::WindDirected), 1.5);
  setValue(beech, GlobalParameter::Kc, 0.7);
  EXPECT_EQ(beech.strand.kc, 0.7);
  setValue(beech, GlobalParameter::Kc, 3.0);  // clamped to [0, 1]
  EXPECT_EQ(beech.strand.kc, 1.0);
  setValue(beech, GlobalParameter::Strands, 1234.6);  // rounded
  EXPECT_EQ(beech.strand.strands, 1235);
  setValue(beech, GlobalParameter::Strands, 0.0);  // at least one strand
  EXPECT_EQ(beech.strand.strands, 1);
  EXPECT_EQ(&graphOf(beech.strand.graphs, LocalGraph::MinLenG), &beech.strand.graphs.minLenG);
  EXPECT_EQ(findLocalGraph("alpha_m_w"), LocalGraph::AlphaMW);
  EXPECT_EQ(findGlobalParameter("flexibility_kf"), GlobalParameter::Flexibility);
  EXPECT_FALSE(findGlobalParameter("ks_g").has_value());
}

}  // namespace eco
