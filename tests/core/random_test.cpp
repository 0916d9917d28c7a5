#include "core/random.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace eco {

TEST(Rng, SameKeyGivesSameStream) {
  Rng a(streamKey(42, 7, purpose("test")));
  Rng b(streamKey(42, 7, purpose("test")));
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.nextBits(), b.nextBits());
}

TEST(Rng, KeysDifferByEveryComponent) {
  std::uint64_t base = streamKey(42, 7, purpose("test"));
  EXPECT_NE(base, streamKey(43, 7, purpose("test")));
  EXPECT_NE(base, streamKey(42, 8, purpose("test")));
  EXPECT_NE(base, streamKey(42, 7, purpose("other")));
  EXPECT_NE(streamKey(1, 2), streamKey(2, 1));  // order matters
}

TEST(Rng, UniformHasTheRightMoments) {
  Rng rng(streamKey(1, purpose("moments")));
  const int n = 200000;
  double sum = 0.0, sumSq = 0.0;
  for (int i = 0; i < n; ++i) {
    double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sumSq += u * u;
  }
  double mean = sum / n;
  EXPECT_NEAR(mean, 0.5, 0.005);  // sd of the mean is 0.00065
  EXPECT_NEAR(sumSq / n - mean * mean, 1.0 / 12.0, 0.002);
}

TEST(Rng, NormalHasZeroMeanUnitVariance) {
  Rng rng(streamKey(2, purpose("normal")));
  const int n = 100000;
  double sum = 0.0, sumSq = 0.0;
  for (int i = 0; i < n; ++i) {
    double x = rng.normal();
    sum += x;
    sumSq += x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.02);
  EXPECT_NEAR(sumSq / n, 1.0, 0.03);
}

TEST(Rng, StochasticRoundKeepsTheExpectation) {
  Rng rng(streamKey(3, purpose("round")));
  const int n = 100000;
  long total = 0;
  for (int i = 0; i < n; ++i) {
    int r = rng.stochasticRound(2.3);
    ASSERT_TRUE(r == 2 || r == 3);
    total += r;
  }
  EXPECT_NEAR(static_cast<double>(total) / n, 2.3, 0.01);
  EXPECT_EQ(rng.stochasticRound(5.0), 5);  // whole numbers stay exact
}

}  // namespace eco
