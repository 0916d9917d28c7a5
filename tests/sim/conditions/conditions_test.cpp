#include "sim/conditions/conditions.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "terrain_support.hpp"

namespace eco {

TEST(Conditions, EveryFieldCoversTheGridInItsRange) {
  Terrain t = generateMidpoint({65, 0.55, 400.0}, 10, 10, 300.0, 3);
  ConditionsReport report;
  ConditionFields f = computeConditions(t, Climate{}, SunlightSettings{}, &report);
  for (const FieldInfo& info : conditionFieldInfo())
    EXPECT_EQ((f.*info.field).size(), t.grid.cellCount()) << info.name;
  EXPECT_EQ(f.altitude_m, t.height_m);
  for (const Field* unit : {&f.windiness, &f.sunniness})
    for (float v : *unit) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
  for (float v : f.moisture) ASSERT_TRUE(v >= 1.0f && v <= 12.0f);  // Ellenberg's F scale
  EXPECT_GT(f.openFlatSunniness, 0.0);
  EXPECT_EQ(report.fieldMilliseconds.size(), 5u);
  EXPECT_GT(report.sunRays, t.grid.cellCount());
}

TEST(Conditions, IdenticalWhateverTheThreadCount) {
  Terrain t = generateMidpoint({65, 0.6, 400.0}, 10, 10, 300.0, 5);
  ConditionFields one, two;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = computeConditions(t, Climate{}, SunlightSettings{});
  }
  {
    tbb::global_control dual(tbb::global_control::max_allowed_parallelism, 2);
    two = computeConditions(t, Climate{}, SunlightSettings{});
  }
  for (const FieldInfo& info : conditionFieldInfo())
    EXPECT_EQ(one.*info.field, two.*info.field) << info.name;
}

}  // namespace eco
