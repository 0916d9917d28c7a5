#include "model/strand_model.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "core/angles.hpp"
#include "model/local_params.hpp"
#include "test_support.hpp"

namespace eco {
namespace {

double angleBetween_deg(glm::vec3 a, glm::vec3 b) {
  double c =
      std::clamp(static_cast<double>(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0);
  return degrees(std::acos(c));
}

struct Children {
  std::int32_t major = -1, minor = -1;
};

std::vector<Children> childrenOf(const TreeSkeleton& tree) {
  std::vector<Children> children(tree.segments.size());
  for (std::size_t i = 1; i < tree.segments.size(); ++i) {
    const BranchSegment& s = tree.segments[i];
    (s.continuesParent ? children[s.parent].major : children[s.parent].minor) =
        static_cast<std::int32_t>(i);
  }
  return children;
}

glm::vec3 leafCentroid(const TreeSkeleton& tree) {
  glm::vec3 sum(0.0f);
  for (const Leaf& leaf : tree.leaves) sum += leaf.position;
  return sum / static_cast<float>(tree.leaves.size());
}

// Mean vertical component of branch axes, weighted by length (1 = all straight up).
double meanUpness(const TreeSkeleton& tree) {
  double sum = 0.0, weight = 0.0;
  for (const BranchSegment& s : tree.segments) {
    sum += s.axis().y * s.length_m;
    weight += s.length_m;
  }
  return sum / weight;
}

}  // namespace

TEST(StrandModel, SegmentCountIsTwoSMinusOne) {
  for (auto [name, strands] : {std::pair{"beech", 1000}, std::pair{"pine", 6000}}) {
    TreeSkeleton tree = buildStrandTree(test::loadNamed(name), {});
    std::size_t terminal = 0;
    for (const BranchSegment& s : tree.segments) terminal += s.isTerminal() ? 1 : 0;
    EXPECT_EQ(tree.segments.size(), 2u * strands - 1u) << name;
    EXPECT_EQ(terminal, static_cast<std::size_t>(strands)) << name;
  }
}

TEST(StrandModel, StrandsAreConservedAtEveryNode) {
  Species pine = test::loadNamed("pine");
  TreeSkeleton tree = buildStrandTree(pine, {});
  auto children = childrenOf(tree);
  EXPECT_EQ(tree.segments[0].strands, 6000);
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const BranchSegment& s = tree.segments[i];
    if (s.isTerminal()) {
      EXPECT_EQ(children[i].major, -1);
      continue;
    }
    ASSERT_GE(children[i].major, 0);
    ASSERT_GE(children[i].minor, 0);
    int s1 = tree.segments[children[i].major].strands,
        s2 = tree.segments[children[i].minor].strands;
    ASSERT_EQ(s1 + s2, s.strands) << "node " << i;
    ASSERT_GE(s1, s2);
    // S1 = ceil(1 + k_s (S0 - 2)) with the local k_s of this node.
    double ks = evaluateLocal(pine.strand.graphs, s.gravelius, s.weibull).ks;
    ASSERT_EQ(s1, std::clamp(static_cast<int>(std::ceil(1.0 + ks * (s.strands - 2) - 1e-9)), 1,
                             s.strands - 1));
    // Orders: the minor child is one Gravelius order up, both one Weibull order up.
    EXPECT_EQ(tree.segments[children[i].minor].gravelius, s.gravelius + 1);
    EXPECT_EQ(tree.segments[children[i].major].gravelius, s.gravelius);
    EXPECT_EQ(tree.segments[children[i].major].weibull, s.weibull + 1);
  }
}

TEST(StrandModel, ThicknessFollowsMandelbrot) {
  Species beech = test::loadNamed("beech");
  TreeSkeleton tree = buildStrandTree(beech, {});
  for (const BranchSegment& s : tree.segments)
    ASSERT_NEAR(2.0 * s.startRadius_m, beech.strand.kd * std::sqrt(s.strands), 1e-6);
  EXPECT_NEAR(2.0 * tree.segments[0].startRadius_m, 0.01 * std::sqrt(1000.0), 1e-6);
}

TEST(StrandModel, SegmentsJoinAndFramesAreOrthonormal) {
  TreeSkeleton tree = buildStrandTree(test::loadNamed("maple"), {.windTime = 1.3});
  for (const BranchSegment& s : tree.segments) {
    glm::mat3 f = s.frame;
    for (int a = 0; a < 3; ++a) {
      ASSERT_NEAR(glm::length(f[a]), 1.0f, 1e-4f);
      ASSERT_NEAR(glm::dot(f[a], f[(a + 1) % 3]), 0.0f, 1e-4f);
    }
    if (s.parent >= 0) {
      ASSERT_LT(glm::length(s.start - tree.segments[s.parent].end()), 1e-5f);
    }
  }
  EXPECT_EQ(tree.segments[0].start, glm::vec3(0.0f));
  EXPECT_NEAR(tree.segments[0].axis().y, 1.0f, 1e-6f);  // the trunk starts upright
}

TEST(StrandModel, BranchingAnglesSumToAlpha) {
  // Without gravimorphism, wind or variation, the angle between the two sub-branches is
  // alpha_1 + alpha_2 = alpha^{g,w}, and the major one deviates by alpha_1.
  Species beech = test::withoutVariation(test::loadNamed("beech"));
  TreeSkeleton tree = buildStrandTree(beech, {.windDirected = 0.0});
  auto children = childrenOf(tree);
  int checked = 0;
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    if (tree.segments[i].isTerminal()) continue;
    const BranchSegment& s = tree.segments[i];
    const BranchSegment& major = tree.segments[children[i].major];
    const BranchSegment& minor = tree.segments[children[i].minor];
    double alpha = evaluateLocal(beech.strand.graphs, s.gravelius, s.weibull).alpha_deg;
    double alpha1 =
        beech.strand.kc * std::sqrt(static_cast<double>(minor.strands) / s.strands) * alpha;
    ASSERT_NEAR(angleBetween_deg(major.axis(), minor.axis()), alpha, 1e-2) << "node " << i;
    ASSERT_NEAR(angleBetween_deg(s.axis(), major.axis()), alpha1, 1e-2) << "node " << i;
    ++checked;
  }
  EXPECT_EQ(checked, 999);
}

TEST(StrandModel, GravimorphismBendsAlongOrAgainstGravity) {
  Species base = test::withoutVariation(test::loadNamed("beech"));
  auto withAlphaM = [&](double degrees) {
    Species s = base;
    s.strand.graphs.alphaMG = Polyline::constant(degrees);
    return meanUpness(buildStrandTree(s, {.windDirected = 0.0, .leaves = false}));
  };
  double none = withAlphaM(0.0);
  // alpha_m > 0 bends toward the downward vertical (the gravimorphism vector is gravity),
  // alpha_m < 0 away from it, up against gravity.
  EXPECT_LT(withAlphaM(+5.0), none - 0.05);
  EXPECT_GT(withAlphaM(-5.0), none + 0.05);
  // Per segment the bend is exactly alpha_m about y x y_m. Four strands split evenly
  // (k_s = 1/2) at 90 degrees with a straight leader (k_c = 0) give a horizontal minor
  // branch of two strands; its major child continues it, turned 30 degrees down.
  Species one = base;
  one.strand.strands = 4;
  one.strand.kc = 0.0;
  one.strand.graphs.ksG = Polyline::constant(0.5);
  one.strand.graphs.alphaG = Polyline::constant(90.0);
  one.strand.graphs.alphaMG = Polyline::constant(30.0);
  TreeSkeleton tree = buildStrandTree(one, {.windDirected = 0.0, .leaves = false});
  auto children = childrenOf(tree);
  const BranchSegment& horizontal = tree.segments[children[0].minor];
  ASSERT_NEAR(horizontal.axis().y, 0.0f, 1e-5f);
  const BranchSegment& continuation = tree.segments[children[children[0].minor].major];
  EXPECT_NEAR(angleBetween_deg(horizontal.axis(), continuation.axis()), 30.0, 1e-3);
  EXPECT_NEAR(continuation.axis().y, -std::sin(30.0 * std::numbers::pi / 180.0), 1e-5);
  // The vertical leader cannot bend: gravity is parallel to it.
  EXPECT_NEAR(tree.segments[children[0].major].axis().y, 1.0f, 1e-5f);
}

TEST(StrandModel, DirectedWindTiltsTheCrownDownwind) {
  Species maple = test::loadNamed("maple");
  const glm::dvec3 east(1.0, 0.0, 0.0);
  glm::vec3 calm = leafCentroid(buildStrandTree(maple, {.windDirected = 0.0}));
  glm::vec3 windy =
      leafCentroid(buildStrandTree(maple, {.windDirected = 6.0, .windDirection = east}));
  EXPECT_GT(windy.x - calm.x, 0.3f);  // metres downwind
  EXPECT_LT(std::abs(windy.z - calm.z), 0.5f * (windy.x - calm.x));
  glm::vec3 west =
      leafCentroid(buildStrandTree(maple, {.windDirected = 6.0, .windDirection = -east}));
  EXPECT_LT(west.x - calm.x, -0.3f);
}

TEST(StrandModel, UndirectedWindSwaysWithTimeUnlessRigid) {
  Species maple = test::loadNamed("maple");  // k_f = 0.6
  glm::vec3 a = leafCentroid(buildStrandTree(maple, {.windTime = 0.0, .windUndirected = 3.0}));
  glm::vec3 b = leafCentroid(buildStrandTree(maple, {.windTime = 1.5, .windUndirected = 3.0}));
  EXPECT_GT(glm::length(a - b), 0.01f);
  Species beech = test::loadNamed("beech");  // the paper's k_f = 1: (1 - k_f) = 0
  glm::vec3 c = leafCentroid(buildStrandTree(beech, {.windTime = 0.0, .windUndirected = 3.0}));
  glm::vec3 d = leafCentroid(buildStrandTree(beech, {.windTime = 1.5, .windUndirected = 3.0}));
  EXPECT_LT(glm::length(c - d), 1e-5f);
}

TEST(StrandModel, SameSeedSameTreeOtherSeedOtherTree) {
  Species beech = test::loadNamed("beech");
  TreeSkeleton a = buildStrandTree(beech, {.seed = 7});
  TreeSkeleton b = buildStrandTree(beech, {.seed = 7});
  TreeSkeleton c = buildStrandTree(beech, {.seed = 8});
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t i = 0; i < a.segments.size(); ++i)
    ASSERT_EQ(a.segments[i].end(), b.segments[i].end());
  ASSERT_EQ(a.leaves.size(), b.leaves.size());
  EXPECT_EQ(a.segments.size(), c.segments.size());  // topology is the species'
  EXPECT_GT(glm::length(leafCentroid(a) - leafCentroid(c)), 0.01f);
}

TEST(StrandModel, GrowthIsContinuousAndMonotone) {
  Species beech = test::loadNamed("beech");
  double previousHeight = 0.0;
  std::size_t previousSegments = 0;
  TreeSkeleton seedling = buildStrandTree(beech, {.age = 0.0});
  EXPECT_GE(seedling.segments.size(), 1u);
  EXPECT_LT(measure(seedling).height_m, 0.1 * measure(buildStrandTree(beech, {})).height_m);
  for (int step = 0; step <= 100; ++step) {
    double age = step / 100.0;
    TreeSkeleton tree = buildStrandTree(beech, {.age = age});
    SkeletonMeasures m = measure(tree);
    ASSERT_GE(m.height_m, previousHeight - 1e-6) << "age " << age;
    ASSERT_GE(tree.segments.size(), previousSegments) << "age " << age;
    // No popping: 1% more age moves the top by well under 1 m (mature height 27 m).
    if (step > 0) {
      ASSERT_LT(m.height_m - previousHeight, 1.0) << "age " << age;
    }
    previousHeight = m.height_m;
    previousSegments = tree.segments.size();
  }
  EXPECT_EQ(previousSegments, 1999u);
}

TEST(StrandModel, SaplingsAreLeafyAndFoliageChangesSmoothly) {
  Species maple = test::loadNamed("maple");
  auto leafArea = [&](double age) {
    double area = 0.0;
    for (const Leaf& leaf : buildStrandTree(maple, {.age = age}).leaves)
      area += leaf.size_m * leaf.size_m;
    return area;
  };
  const double mature = leafArea(1.0);
  EXPECT_GT(leafArea(0.0), 0.0) << "even a seedling has leaves";
  EXPECT_GT(buildStrandTree(maple, {.age = 0.25}).leaves.size(), 100u);
  // Continuous, not popping: the change shrinks with the step. Whole branch orders hand
  // over together, so foliage changes fastest there; 0.1% of age never moves more than
  // 3% of the mature leaf area, 0.01% never more than 0.3%.
  for (double step : {0.001, 0.0001}) {
    double worst = 0.0;
    for (double age = 0.0; age + step <= 1.0; age += step < 0.001 ? 0.0137 : step)
      worst = std::max(worst, std::abs(leafArea(age + step) - leafArea(age)));
    EXPECT_LT(worst, 30.0 * step * mature) << "step " << step;
  }
  EXPECT_EQ(buildStrandTree(maple, {}).leaves.size(), 6000u);  // mature: terminal strands only
}

TEST(StrandModel, NewSegmentsEmergeAtZeroLength) {
  Species beech = test::loadNamed("beech");
  TreeSkeleton before = buildStrandTree(beech, {.age = 0.5});
  TreeSkeleton after = buildStrandTree(beech, {.age = 0.5005});
  ASSERT_GT(after.segments.size(), 0u);
  // Segments present in both keep nearly their length; newcomers are short.
  std::size_t grown = 0;
  for (const BranchSegment& s : after.segments) grown += s.length_m < 0.05f ? 1 : 0;
  EXPECT_GE(grown, after.segments.size() - before.segments.size());
}

TEST(StrandModel, SingleStrandIsATrunkWithLeaves) {
  Species beech = test::loadNamed("beech");
  beech.strand.strands = 1;
  TreeSkeleton tree = buildStrandTree(beech, {});
  EXPECT_EQ(tree.segments.size(), 1u);
  EXPECT_EQ(tree.leaves.size(), 5u);
}

}  // namespace eco
