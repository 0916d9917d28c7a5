#include "sim/conditions/condition_maps.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "sim/image_io.hpp"
#include "test_files.hpp"

namespace eco {

TEST(ConditionMaps, WritesRawFloatsColourMapsAndSummary) {
  auto dir = test::freshDirectory("maps");
  Terrain t = generateMidpoint({33, 0.55, 200.0}, 10, 10, 100.0, 1);
  ConditionsReport report;
  ConditionFields f = computeConditions(t, Climate{}, SunlightSettings{}, &report);
  Scenario scenario;
  scenario.name = "test";
  writeConditionOutputs(f, report, scenario, dir);
  for (const FieldInfo& info : conditionFieldInfo()) {
    SingleChannelImage raw = readSingleChannel(dir / "maps" / (std::string(info.name) + ".exr"));
    EXPECT_EQ(raw.values, f.*info.field) << info.name;
    EXPECT_TRUE(std::filesystem::exists(dir / "maps" / (std::string(info.name) + ".png")));
  }
  nlohmann::json summary = nlohmann::json::parse(test::readFile(dir / "conditions.json"));
  EXPECT_EQ(summary["grid"]["width"], 33);
  EXPECT_EQ(summary["fields"]["altitude"]["min"].get<double>(), 100.0);
  EXPECT_TRUE(summary["fields"]["sunniness"].contains("ms"));
  EXPECT_GT(summary["sun_rays"].get<double>(), 0.0);
}

TEST(ConditionMaps, RampsRunBetweenTheirEnds) {
  glm::vec3 low = rampColor("moisture", 0.0), high = rampColor("moisture", 1.0);
  EXPECT_GT(high.b, low.b);                                       // wet is blue
  EXPECT_EQ(rampColor("aspect", 0.0), rampColor("aspect", 1.0));  // aspect is cyclic
  EXPECT_EQ(rampColor("slope", -5.0), rampColor("slope", 0.0));   // clamped
}

}  // namespace eco
