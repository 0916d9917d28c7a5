#include "sim/terrain.hpp"

#include <gtest/gtest.h>

#include "sim/conditions/conditions.hpp"
#include "sim/image_io.hpp"
#include "terrain_support.hpp"
#include "test_files.hpp"

namespace eco {

TEST(Terrain, HeightRangeMapsIntegerImages) {
  auto dir = test::freshDirectory("terrain16");
  writeUint16Image(dir / "h.png", 2, 2, {0, 65535, 32768, 13107});
  Terrain t = readHeightmap(dir / "h.png", 10, 10, 200.0, 900.0);
  EXPECT_FLOAT_EQ(t.height_m[0], 200.0f);
  EXPECT_FLOAT_EQ(t.height_m[1], 900.0f);
  EXPECT_NEAR(t.height_m[3], 200.0 + 700.0 * 0.2, 1e-3);
  Terrain raw = readHeightmap(dir / "h.png", 10, 10, {}, {});
  EXPECT_FLOAT_EQ(raw.height_m[2], 32768.0f);  // no range: stored values are metres
}

TEST(Terrain, PngTiffAndExrGiveTheSameFields) {
  auto dir = test::freshDirectory("terrainformats");
  Terrain hills = test::analyticTerrain(40, 32, 10, 10, [](double e, double n) {
    return 300.0 + 100.0 * (0.5 + 0.5 * std::sin(e / 60.0) * std::cos(n / 45.0));
  });
  // Quantise to 16 bits first so that every format holds exactly the same heights.
  writeHeightmap16(hills, dir / "h.png", 300.0, 400.0);
  Terrain fromPng = readHeightmap(dir / "h.png", 10, 10, 300.0, 400.0);
  writeFloatImage(dir / "h.tif", 40, 32, 1, fromPng.height_m);
  writeFloatImage(dir / "h.exr", 40, 32, 1, fromPng.height_m);
  Terrain fromTiff = readHeightmap(dir / "h.tif", 10, 10, {}, {});
  Terrain fromExr = readHeightmap(dir / "h.exr", 10, 10, {}, {});
  ConditionFields a = computeConditions(fromPng, Climate{}, SunlightSettings{});
  ConditionFields b = computeConditions(fromTiff, Climate{}, SunlightSettings{});
  ConditionFields c = computeConditions(fromExr, Climate{}, SunlightSettings{});
  for (const FieldInfo& info : conditionFieldInfo()) {
    EXPECT_EQ(a.*info.field, b.*info.field) << info.name;
    EXPECT_EQ(a.*info.field, c.*info.field) << info.name;
  }
}

TEST(Terrain, MidpointDisplacementIsDeterministicAndScaled) {
  GeneratedTerrain settings{65, 0.55, 300.0};
  Terrain a = generateMidpoint(settings, 10, 10, 200.0, 7);
  Terrain b = generateMidpoint(settings, 10, 10, 200.0, 7);
  Terrain c = generateMidpoint(settings, 10, 10, 200.0, 8);
  EXPECT_EQ(a.height_m, b.height_m);
  EXPECT_NE(a.height_m, c.height_m);
  FieldStats s = statsOf(a.height_m);
  EXPECT_FLOAT_EQ(s.min, 200.0);
  EXPECT_NEAR(s.max, 500.0, 1e-3);
  // Rougher settings give rougher ground: a larger mean slope.
  auto meanStep = [](const Terrain& t) {
    double sum = 0.0;
    for (int y = 0; y < t.grid.height; ++y)
      for (int x = 1; x < t.grid.width; ++x)
        sum += std::abs(t.heightAt(x, y) - t.heightAt(x - 1, y));
    return sum;
  };
  EXPECT_GT(meanStep(generateMidpoint({65, 0.8, 300.0}, 10, 10, 0.0, 7)),
            1.5 * meanStep(generateMidpoint({65, 0.4, 300.0}, 10, 10, 0.0, 7)));
}

TEST(Terrain, CarriesWhatItsClosedDepressionsAre) {
  Scenario scenario;
  scenario.terrain.generate = GeneratedTerrain{9, 0.5, 10.0};
  EXPECT_EQ(loadTerrain(scenario).closedDepressions, ClosedDepressions::Drain);
  scenario.terrain.closedDepressions = ClosedDepressions::Pond;
  EXPECT_EQ(loadTerrain(scenario).closedDepressions, ClosedDepressions::Pond);
}

}  // namespace eco
