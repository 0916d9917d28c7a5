#include "model/lsystem/random.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace eco {
namespace {

struct Moments {
  double mean = 0.0;
  double variance = 0.0;
};

Moments sample(const RandomVariable& v, int n) {
  double sum = 0.0, squares = 0.0;
  for (int i = 0; i < n; ++i) {
    Rng rng(streamKey(99, static_cast<std::uint64_t>(i)));
    const double x = v.sample(rng);
    sum += x;
    squares += x * x;
  }
  const double mean = sum / n;
  return {mean, squares / n - mean * mean};
}

// Sample mean within 5 standard errors of the distribution's mean, and the sample variance
// within 5 % (plus 5 standard errors of the mean's scale for tiny variances).
void expectMoments(const RandomVariable& v) {
  constexpr int kSamples = 200000;
  const Moments m = sample(v, kSamples);
  const double standardError = std::sqrt(v.variance() / kSamples);
  EXPECT_NEAR(m.mean, v.mean(), 5.0 * standardError + 1e-12) << distributionName(v.distribution);
  EXPECT_NEAR(m.variance, v.variance(), 0.05 * v.variance() + 1e-12)
      << distributionName(v.distribution);
}

TEST(LSystemRandom, EveryDistributionHasItsMeanAndVariance) {
  expectMoments({"c", false, Distribution::Constant, 2.5, 0});
  expectMoments({"u", false, Distribution::Uniform, -1.0, 3.0});
  expectMoments({"e", false, Distribution::Exponential, 0.5, 0});
  expectMoments({"n", false, Distribution::Normal, 10.0, 2.0});
  expectMoments({"k", true, Distribution::Constant, 4, 0});
  expectMoments({"d", true, Distribution::Uniform, 1, 6});
  expectMoments({"b", true, Distribution::Binomial, 20, 0.3});
  expectMoments({"p", true, Distribution::Poisson, 3.5, 0});
  expectMoments({"q", true, Distribution::Poisson, 250, 0});
}

TEST(LSystemRandom, DiscreteVariablesTakeIntegersInTheirRange) {
  const RandomVariable dice{"d", true, Distribution::Uniform, 1, 6};
  int seen[7] = {};
  for (int i = 0; i < 6000; ++i) {
    Rng rng(streamKey(5, static_cast<std::uint64_t>(i)));
    const double x = dice.sample(rng);
    ASSERT_EQ(x, std::floor(x));
    ASSERT_GE(x, 1);
    ASSERT_LE(x, 6);
    ++seen[static_cast<int>(x)];
  }
  for (int face = 1; face <= 6; ++face) EXPECT_NEAR(seen[face], 1000, 150) << face;
}

TEST(LSystemRandom, InvalidParametersAreExplained) {
  EXPECT_EQ(checkRandomVariable({"u", false, Distribution::Uniform, 2, 1}),
            "UNIFORM(a, b) needs a <= b");
  EXPECT_EQ(checkRandomVariable({"e", false, Distribution::Exponential, 0, 0}),
            "EXPONENTIAL(rate) needs rate > 0");
  EXPECT_EQ(checkRandomVariable({"b", true, Distribution::Binomial, 10, 1.5}),
            "BINOMIAL(n, p) needs p in 0..1");
  EXPECT_EQ(checkRandomVariable({"p", false, Distribution::Poisson, 3, 0}),
            "POISSON is a DISCRETE distribution");
  EXPECT_EQ(checkRandomVariable({"n", true, Distribution::Normal, 0, 1}),
            "NORMAL is a CONTINUOUS distribution");
  EXPECT_TRUE(checkRandomVariable({"n", false, Distribution::Normal, 0, 1}).empty());
}

TEST(LSystemRandom, DeviatesDependOnlyOnKeyVariableAndOccurrence) {
  const std::vector<RandomVariable> variables{{"u", false, Distribution::Uniform, 0, 1},
                                              {"v", false, Distribution::Uniform, 0, 1}};
  const VariableDeviates a(variables, 42), b(variables, 42), other(variables, 43);
  EXPECT_EQ(a.deviate(0, 0), b.deviate(0, 0));
  EXPECT_EQ(a.deviate(1, 2), b.deviate(1, 2));
  EXPECT_NE(a.deviate(0, 0), a.deviate(0, 1));
  EXPECT_NE(a.deviate(0, 0), a.deviate(1, 0));
  EXPECT_NE(a.deviate(0, 0), other.deviate(0, 0));
}

}  // namespace
}  // namespace eco
