#include "sim/conditions/condition_maps.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "sim/image_io.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

// Width and height from a PNG's header chunk.
std::pair<int, int> pngSize(const std::filesystem::path& file) {
  const std::string bytes = test::readFile(file);
  auto big = [&](std::size_t at) {
    int v = 0;
    for (std::size_t i = at; i < at + 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[i]);
    return v;
  };
  return bytes.size() > 24 ? std::make_pair(big(16), big(20)) : std::make_pair(0, 0);
}

}  // namespace

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
    // The same floats georeferenced, and a preview of one pixel per cell with its world file
    // and its legend beside it.
    const std::string stem = (dir / "maps" / info.name).string();
    EXPECT_EQ(readSingleChannel(stem + ".tif").values, f.*info.field) << info.name;
    EXPECT_EQ(pngSize(stem + ".png"), std::make_pair(f.grid.width, f.grid.height));
    EXPECT_TRUE(std::filesystem::exists(stem + ".pgw"));
    EXPECT_TRUE(std::filesystem::exists(stem + "_legend.png"));
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

// The plan's codes keep their colours whatever codes a map holds: a map of only planted (3)
// and kept-open (4) cells does not stretch them over the ramp.
TEST(ConditionMaps, ThePlansCodesHaveFixedColours) {
  EXPECT_EQ(rampRange("plan", "0-4", {3.0, 3.5, 4.0}), std::make_pair(0.0, 4.0));
  EXPECT_EQ(rampRange("suitability_beech", "", {0.2, 0.5, 0.7}), std::make_pair(0.0, 1.0));
  EXPECT_EQ(rampRange("altitude", "m", {200.0, 300.0, 400.0}), std::make_pair(200.0, 400.0));
  const Grid grid{2, 1, 10.0, 10.0};
  const auto dir = test::freshDirectory("condition_maps_plan");
  writeFieldMap(dir, "plan", "0-4", {3.0f, 4.0f}, grid);
  for (int code = 1; code <= 4; ++code)
    EXPECT_NE(rampColor("plan", code / 4.0), rampColor("plan", (code - 1) / 4.0)) << code;
  EXPECT_EQ(pngSize(dir / "plan_legend.png"), std::make_pair(480, 34));
}

}  // namespace eco
