#include "model/local_params.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace eco {
namespace {

LocalGraphs constantGraphs(double ksG, double ksW, double aG, double aW, double amG, double amW) {
  LocalGraphs g;
  g.ksG = Polyline::constant(ksG);
  g.ksW = Polyline::constant(ksW);
  g.alphaG = Polyline::constant(aG);
  g.alphaW = Polyline::constant(aW);
  g.alphaMG = Polyline::constant(amG);
  g.alphaMW = Polyline::constant(amW);
  g.maxLenG = Polyline::constant(3.0);
  g.maxLenW = Polyline::constant(1.5);
  g.klG = Polyline::constant(0.5);
  g.klW = Polyline::constant(1.2);
  g.minLenG = Polyline::constant(0.4);
  g.minLenW = Polyline::constant(0.25);
  return g;
}

}  // namespace

TEST(LocalParams, Eq1ClampsStrandDistributionToHalfAndOne) {
  EXPECT_DOUBLE_EQ(evaluateLocal(constantGraphs(0.8, 1.5, 0, 0, 0, 0), 0, 0).ks, 1.0);
  EXPECT_DOUBLE_EQ(evaluateLocal(constantGraphs(0.8, 0.5, 0, 0, 0, 0), 0, 0).ks, 0.5);
  EXPECT_DOUBLE_EQ(evaluateLocal(constantGraphs(0.8, 0.9, 0, 0, 0, 0), 0, 0).ks, 0.8 * 0.9);
}

TEST(LocalParams, Eq2And3ClampAngles) {
  EXPECT_DOUBLE_EQ(evaluateLocal(constantGraphs(1, 1, 120, 2, 0, 0), 0, 0).alpha_deg, 180.0);
  EXPECT_DOUBLE_EQ(evaluateLocal(constantGraphs(1, 1, 40, 1.5, 0, 0), 0, 0).alpha_deg, 60.0);
  EXPECT_DOUBLE_EQ(evaluateLocal(constantGraphs(1, 1, 0, 0, 150, 2), 0, 0).alphaM_deg, 180.0);
  EXPECT_DOUBLE_EQ(evaluateLocal(constantGraphs(1, 1, 0, 0, -150, 2), 0, 0).alphaM_deg, -180.0);
  EXPECT_DOUBLE_EQ(evaluateLocal(constantGraphs(1, 1, 0, 0, -30, 0.5), 0, 0).alphaM_deg, -15.0);
}

TEST(LocalParams, Eq4To6ArePlainProducts) {
  LocalParams p = evaluateLocal(constantGraphs(1, 1, 0, 0, 0, 0), 0, 0);
  EXPECT_DOUBLE_EQ(p.maxLength, 4.5);
  EXPECT_DOUBLE_EQ(p.kl, 0.6);
  EXPECT_DOUBLE_EQ(p.minLength, 0.1);
}

TEST(LocalParams, PineAcrossTheKsWStep) {
  Species pine = test::loadNamed("pine");
  const LocalGraphs& g = pine.strand.graphs;
  // g = 0, w = 45: k_s^g = 0.955; k_s^w after the step at 42.89.
  double ksW = 0.654 + (45.0 - 42.89) / (50.0 - 42.89) * (0.6256 - 0.654);
  EXPECT_NEAR(evaluateLocal(g, 0, 45).ks, std::max(0.955 * ksW, 0.5), 1e-12);
  // g = 0, w = 42: 0.955 * 1.0049 < 1, no clamp.
  EXPECT_NEAR(evaluateLocal(g, 0, 42).ks, 0.955 * (1.0 + 0.005 * 42.0 / 42.89), 1e-12);
  // g = 2 lies between control points 1.827 and 4.207 of k_s^g.
  double ksG = 0.8288 + (2.0 - 1.827) / (4.207 - 1.827) * (0.8269 - 0.8288);
  EXPECT_NEAR(evaluateLocal(g, 2, 10).ks, ksG * (1.0 + 0.005 * 10.0 / 42.89), 1e-12);
  // Gravimorphism at g = 1, between 0.3875 and 1.034.
  double am = 34.62 + (1.0 - 0.3875) / (1.034 - 0.3875) * (-4.265 - 34.62);
  EXPECT_NEAR(evaluateLocal(g, 1, 3).alphaM_deg, am, 1e-9);
  // k_l at w = 50 is the paper's 0.01896 times k_l^g(15) = 1.
  EXPECT_NEAR(evaluateLocal(g, 15, 50).kl, 0.01896, 1e-12);
}

}  // namespace eco
