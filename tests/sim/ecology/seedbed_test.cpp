#include "sim/ecology/seedbed.hpp"

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(Seedbed, OpenFreshGroundIsASwardThatShadeDryGroundAndRockThin) {
  const float meadow = swardShare(1.0f, 5.0f, 5.0f);
  EXPECT_FLOAT_EQ(meadow, 0.9f);  // a tenth stays bare between the tussocks
  // Grasses need light: none where the canopy lets through 40 % or less.
  EXPECT_FLOAT_EQ(swardShare(0.4f, 5.0f, 5.0f), 0.0f);
  EXPECT_FLOAT_EQ(swardShare(0.1f, 5.0f, 5.0f), 0.0f);
  float last = 0.0f;
  for (float light = 0.4f; light <= 1.0f; light += 0.05f) {
    const float sward = swardShare(light, 5.0f, 5.0f);
    EXPECT_GE(sward, last) << light;  // closes as the light grows
    last = sward;
  }
  // Dry ground (F 2 and less) is bare; F 3 a dry grassland half as dense; F 4 a meadow.
  EXPECT_FLOAT_EQ(swardShare(1.0f, 2.0f, 5.0f), 0.0f);
  EXPECT_FLOAT_EQ(swardShare(1.0f, 3.0f, 5.0f), 0.5f * meadow);
  EXPECT_FLOAT_EQ(swardShare(1.0f, 4.0f, 5.0f), meadow);
  // Soil up to 40°, rock from 50°.
  EXPECT_FLOAT_EQ(soilShareOnSlope(40.0f), 1.0f);
  EXPECT_FLOAT_EQ(soilShareOnSlope(45.0f), 0.5f);
  EXPECT_FLOAT_EQ(soilShareOnSlope(50.0f), 0.0f);
  EXPECT_FLOAT_EQ(swardShare(1.0f, 5.0f, 30.0f), meadow);
  EXPECT_FLOAT_EQ(swardShare(1.0f, 5.0f, 55.0f), 0.0f);
}

TEST(Seedbed, LitterUnderACanopyThatTakesMoreThanHalfTheLightElseTheSward) {
  const Seedbed shaded = seedbedAt(0.49, 5.0f, 5.0f);
  EXPECT_TRUE(shaded.litter);
  EXPECT_EQ(shaded.sward, 0.0);
  for (double light : {0.5, 0.7, 1.0}) {
    const Seedbed lit = seedbedAt(light, 5.0f, 5.0f);
    EXPECT_FALSE(lit.litter) << light;
    EXPECT_EQ(lit.sward, swardShare(static_cast<float>(light), 5.0f, 5.0f)) << light;
  }
}

TEST(Seedbed, ASpeciesTakesOnLitterSwardAndBareSoilByItsShares) {
  LifeHistory pine;
  pine.litterEstablishment = 0.2;
  pine.swardEstablishment = 0.3;
  // Under a canopy that takes more than half the light: litter, whatever the sward.
  EXPECT_DOUBLE_EQ(seedbedEstablishment(pine, seedbedAt(0.49, 5.0f, 5.0f)), 0.2);
  EXPECT_DOUBLE_EQ(seedbedEstablishment(pine, {true, 0.9}), 0.2);
  // In the light: bare soil where the sward leaves it.
  EXPECT_DOUBLE_EQ(seedbedEstablishment(pine, {false, 0.0}), 1.0);
  EXPECT_DOUBLE_EQ(seedbedEstablishment(pine, {false, 0.9}), 0.1 + 0.9 * 0.3);
  EXPECT_DOUBLE_EQ(seedbedEstablishment(pine, {false, 1.0}), 0.3);
  // A species whose seeds take anywhere takes exactly as on bare soil.
  const LifeHistory beech;
  for (double sward : {0.0, 0.37, 0.9, 1.0})
    EXPECT_EQ(seedbedEstablishment(beech, {false, sward}), 1.0) << sward;
}

}  // namespace
}  // namespace eco
