#include "sim/run/trees_geojson.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "gdal_tools.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

TreeSnapshot twoTrees() {
  TreeSnapshot s;
  s.year = 30;
  s.speciesNames = {"beech", "pine \"sylvestris\""};
  s.trees = {{.id = 4,
              .species = 0,
              .east_m = 10.5,
              .north_m = 20.25,
              .ground_m = 400.0,
              .age_years = 12,
              .height_m = 9.5f,
              .crownRadius_m = 1.5f,
              .dbh_m = 0.125f,
              .vigor = 0.75f},
             {.id = 9, .species = 1, .east_m = 0.0, .north_m = 0.0, .ground_m = 410.5}};
  return s;
}

TEST(TreesGeoJson, OnePointPerTreeInTheGridsCoordinatesWithItsRow) {
  const auto dir = test::freshDirectory("trees_geojson");
  Grid g{10, 10, 8.0, 8.0};
  g.originEast_m = 612004.0;
  g.originNorth_m = 5229852.0;
  g.epsg = 25832;
  writeTreesGeoJson(dir / "t.geojson", twoTrees(), g);
  const nlohmann::json json = nlohmann::json::parse(test::readFile(dir / "t.geojson"));
  EXPECT_EQ(json["crs"]["properties"]["name"], "urn:ogc:def:crs:EPSG::25832");
  ASSERT_EQ(json["features"].size(), 2u);
  const nlohmann::json& first = json["features"][0];
  EXPECT_EQ(first["geometry"]["coordinates"], nlohmann::json::array({612014.5, 5229872.25, 400.0}));
  EXPECT_EQ(first["properties"]["id"], 4);
  EXPECT_EQ(first["properties"]["species"], "beech");
  EXPECT_EQ(first["properties"]["age"], 12);
  EXPECT_EQ(first["properties"]["dbh_m"], 0.125);
  EXPECT_EQ(json["features"][1]["properties"]["species"], "pine \"sylvestris\"");  // escaped
}

// Written in batches (export's), a later batch naming a new species: the bytes of the
// whole written at once, and valid JSON with or without features.
TEST(TreesGeoJson, BatchesWriteTheBytesOfTheWhole) {
  const auto dir = test::freshDirectory("trees_geojson_batches");
  const Grid g{10, 10, 8.0, 8.0};
  const TreeSnapshot trees = twoTrees();
  writeTreesGeoJson(dir / "whole.geojson", trees, g);
  TreesGeoJsonWriter writer(dir / "batches.geojson", g, trees.year);
  writer.write(std::span(trees.trees).first(1), {trees.speciesNames[0]});
  writer.write({}, {trees.speciesNames[0]});
  writer.write(std::span(trees.trees).subspan(1), trees.speciesNames);
  writer.commit();
  EXPECT_EQ(test::readFile(dir / "batches.geojson"), test::readFile(dir / "whole.geojson"));
  TreesGeoJsonWriter none(dir / "none.geojson", g, trees.year);
  none.commit();
  EXPECT_TRUE(nlohmann::json::parse(test::readFile(dir / "none.geojson"))["features"].empty());
}

TEST(TreesGeoJson, LocalMetresNameNoSystem) {
  const auto dir = test::freshDirectory("trees_geojson_local");
  writeTreesGeoJson(dir / "t.geojson", twoTrees(), Grid{10, 10, 10.0, 10.0});
  const nlohmann::json json = nlohmann::json::parse(test::readFile(dir / "t.geojson"));
  EXPECT_FALSE(json.contains("crs"));
  EXPECT_EQ(json["features"][0]["geometry"]["coordinates"][0], 10.5);
}

TEST(TreesGeoJson, OgrReadsOneFeaturePerTreeInItsSystem) {
  if (!test::gdalInstalled())
    GTEST_SKIP() << "gdal-bin is not installed (scripts/test installs it)";
  const auto dir = test::freshDirectory("trees_geojson_ogr");
  Grid g{10, 10, 8.0, 8.0};
  g.epsg = 25832;
  writeTreesGeoJson(dir / "t.geojson", twoTrees(), g);
  const test::CommandResult r =
      test::runCommand("ogrinfo -ro -so " + (dir / "t.geojson").string() + " trees_year_0030");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("Feature Count: 2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ID[\"EPSG\",25832]"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("species: String"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace eco
