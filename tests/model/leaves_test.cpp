#include "model/leaves.hpp"
#include "core/angles.hpp"

#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace eco {
namespace {

BranchSegment horizontalTwig() {
  BranchSegment twig;
  twig.frame = glm::mat3(glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, -1));  // axis +x
  twig.length_m = 0.5f;
  twig.strands = 1;
  return twig;
}

std::vector<Leaf> place(LeafDistribution distribution, int count) {
  std::vector<Leaf> leaves;
  Rng rng(streamKey(1, purpose("leaves-test")));
  placeLeaves(horizontalTwig(), 3, makeLeafPattern(distribution, count), 0.2f, rng, leaves);
  return leaves;
}

// Azimuth of the blade around the twig axis (+x), degrees in [0, 360).
double azimuth_deg(const Leaf& leaf) {
  double a = degrees(std::atan2(-leaf.direction.z, leaf.direction.y));
  return a < 0 ? a + 360.0 : a;
}

}  // namespace

TEST(Leaves, CountSizeKindAndUnitVectors) {
  for (LeafDistribution d :
       {LeafDistribution::Spiral, LeafDistribution::Stacked, LeafDistribution::Staggered,
        LeafDistribution::Bunched, LeafDistribution::Coniferous}) {
    std::vector<Leaf> leaves = place(d, 8);
    ASSERT_EQ(leaves.size(), 8u) << toString(d);
    for (const Leaf& leaf : leaves) {
      EXPECT_NEAR(glm::length(leaf.direction), 1.0f, 1e-5f);
      EXPECT_NEAR(glm::length(leaf.normal), 1.0f, 1e-5f);
      EXPECT_NEAR(glm::dot(leaf.direction, leaf.normal), 0.0f, 1e-5f);
      EXPECT_EQ(leaf.segment, 3);
      EXPECT_FLOAT_EQ(leaf.size_m, 0.2f);
      EXPECT_GE(leaf.position.x, 0.0f);
      EXPECT_LE(leaf.position.x, 0.5f + 1e-6f);
      EXPECT_EQ(leaf.kind, d == LeafDistribution::Coniferous ? LeafKind::Needle : LeafKind::Card);
    }
  }
}

TEST(Leaves, TheFiveDistributionsDiffer) {
  // Spiral: every leaf at its own position and azimuth, spread all round.
  std::vector<Leaf> spiral = place(LeafDistribution::Spiral, 8);
  std::set<int> spiralPositions, spiralSectors;
  for (const Leaf& l : spiral) {
    spiralPositions.insert(static_cast<int>(std::lround(l.position.x * 1000)));
    spiralSectors.insert(static_cast<int>(azimuth_deg(l) / 90.0));
  }
  EXPECT_EQ(spiralPositions.size(), 8u);
  EXPECT_EQ(spiralSectors.size(), 4u);

  // Stacked: opposite pairs at shared positions, pairs turned about 90 degrees.
  std::vector<Leaf> stacked = place(LeafDistribution::Stacked, 8);
  for (int p = 0; p < 4; ++p) {
    EXPECT_FLOAT_EQ(stacked[2 * p].position.x, stacked[2 * p + 1].position.x);
    double opposite = std::abs(azimuth_deg(stacked[2 * p]) - azimuth_deg(stacked[2 * p + 1]));
    EXPECT_NEAR(opposite, 180.0, 25.0);
  }

  // Staggered: one plane (two azimuths), alternating.
  std::vector<Leaf> staggered = place(LeafDistribution::Staggered, 8);
  for (std::size_t i = 0; i + 1 < staggered.size(); ++i) {
    double a = azimuth_deg(staggered[i]), b = azimuth_deg(staggered[i + 1]);
    EXPECT_NEAR(std::abs(a - b), 180.0, 25.0);
    EXPECT_LT(staggered[i].position.x, staggered[i + 1].position.x);
  }

  // Bunched: all at the tip.
  for (const Leaf& l : place(LeafDistribution::Bunched, 8)) EXPECT_FLOAT_EQ(l.position.x, 0.5f);

  // Coniferous: needles, pointing closer to the twig axis than spiral leaves.
  double coniferAngle = 0.0, spiralAngle = 0.0;
  for (const Leaf& l : place(LeafDistribution::Coniferous, 8))
    coniferAngle += std::acos(l.direction.x);
  for (const Leaf& l : spiral) spiralAngle += std::acos(l.direction.x);
  EXPECT_LT(coniferAngle, spiralAngle - 0.5);
}

TEST(Leaves, BladesFaceTheSky) {
  for (const Leaf& l : place(LeafDistribution::Spiral, 12)) EXPECT_GE(l.normal.y, 0.0f);
}

}  // namespace eco
