#include "sim/geotiff.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "gdal_tools.hpp"
#include "sim/image_io.hpp"
#include "sim/terrain.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

// A 20 x 10 grid of 8 m cells in ETRS89 / UTM 32N.
Grid placedGrid() {
  Grid g{20, 10, 8.0, 8.0};
  g.originEast_m = 500004.0;  // the centre of the south-west cell
  g.originNorth_m = 5199924.0;
  g.epsg = 25832;
  return g;
}

Field ramp(const Grid& g) {
  Field f(g.cellCount());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = 300.0f + static_cast<float>(i);
  return f;
}

TEST(GeoTiff, WrittenTagsReadBackAsTheyWere) {
  const auto dir = test::freshDirectory("geotiff_roundtrip");
  const Grid g = placedGrid();
  Field values = ramp(g);
  values[3] = std::nanf("");
  writeGeoTiff(dir / "m.tif", g, values);
  const GeoTiffTags tags = readGeoTiffTags(dir / "m.tif");
  ASSERT_TRUE(tags.georeferenced);
  EXPECT_EQ(tags.pixelWidth_m, 8.0);
  EXPECT_EQ(tags.pixelHeight_m, 8.0);
  EXPECT_EQ(tags.westEdge_m, 500000.0);
  EXPECT_EQ(tags.northEdge_m, 5200000.0);  // 5199924 + 9.5 cells
  EXPECT_EQ(tags.epsg, 25832);
  ASSERT_TRUE(tags.noData);
  EXPECT_TRUE(std::isnan(*tags.noData));
  // The pixels, as any reader sees them, are the values; placing a grid by the tags gives
  // the grid back.
  const SingleChannelImage image = readSingleChannel(dir / "m.tif", true);
  EXPECT_TRUE(std::isnan(image.values[3]));
  EXPECT_EQ(image.values[4], values[4]);
  Grid placed{20, 10};
  placeGrid(tags, placed);
  EXPECT_EQ(placed.originEast_m, g.originEast_m);
  EXPECT_EQ(placed.originNorth_m, g.originNorth_m);
  EXPECT_EQ(placed.dx_m, 8.0);
}

TEST(GeoTiff, APlainTiffIsNotGeoreferenced) {
  const auto dir = test::freshDirectory("geotiff_plain");
  writeFloatImage(dir / "h.tif", 4, 4, 1, Field(16, 1.0f));
  const GeoTiffTags tags = readGeoTiffTags(dir / "h.tif");
  EXPECT_FALSE(tags.georeferenced);
  EXPECT_FALSE(tags.noData);
  EXPECT_THROW(readGeoTiffTags(dir / "missing.tif"), InputError);
}

TEST(GeoTiff, WorldFileAndAuxPlaceTheCellCentres) {
  const auto dir = test::freshDirectory("geotiff_world");
  writeImageGeoreference(dir / "m.png", placedGrid());
  EXPECT_EQ(test::readFile(dir / "m.pgw"), "8\n0\n0\n-8\n500004.0000000000\n5199996.0000000000\n");
  EXPECT_NE(test::readFile(dir / "m.png.aux.xml").find("EPSG:25832"), std::string::npos);
  Grid local{4, 4, 10.0, 10.0};  // local metres: no coordinate system to name
  writeImageGeoreference(dir / "l.png", local);
  EXPECT_FALSE(std::filesystem::exists(dir / "l.png.aux.xml"));
}

// GDAL, what QGIS uses, reads ecoforest's GeoTIFF and PNG maps at the same place.
TEST(GeoTiff, GdalReadsTheMapsWhereTheyBelong) {
  if (!test::gdalInstalled())
    GTEST_SKIP() << "gdal-bin is not installed (scripts/test installs it)";
  const auto dir = test::freshDirectory("geotiff_gdal");
  const Grid g = placedGrid();
  writeGeoTiff(dir / "m.tif", g, ramp(g));
  writeRgba8Image(dir / "m.png", Image(g.width, g.height));
  writeImageGeoreference(dir / "m.png", g);
  for (const char* name : {"m.tif", "m.png"}) {
    SCOPED_TRACE(name);
    const nlohmann::json info = test::gdalInfo(dir / name);
    EXPECT_EQ(info["geoTransform"],
              nlohmann::json::array({500000.0, 8.0, 0.0, 5200000.0, 0.0, -8.0}));
    EXPECT_EQ(test::gdalEpsg(info), 25832);
  }
  const nlohmann::json tif = test::gdalInfo(dir / "m.tif");
  EXPECT_EQ(tif["bands"][0]["type"], "Float32");
  EXPECT_EQ(tif["bands"][0]["noDataValue"], "NaN");
}

// A GeoTIFF as a GIS writes it: 8 m pixels in UTM, -9999 as no-data.
class GdalHeightmap : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::gdalInstalled())
      GTEST_SKIP() << "gdal-bin is not installed (scripts/test installs it)";
    dir_ = test::freshDirectory("geotiff_heightmap");
    Field heights(30 * 20);
    for (int y = 0; y < 20; ++y)
      for (int x = 0; x < 30; ++x) heights[y * 30 + x] = 400.0f + 2.0f * x + 1.0f * y;
    for (int y = 0; y < 5; ++y)
      for (int x = 0; x < 6; ++x) heights[y * 30 + x] = -9999.0f;  // the north-west corner
    writeFloatImage(dir_ / "raw.tif", 30, 20, 1, heights);
    test::gdalGeoreference(dir_ / "raw.tif", file(), 25832, 612000.0, 5230000.0, 8.0, 30, 20,
                           -9999.0);
  }
  std::filesystem::path file() const { return dir_ / "dem.tif"; }
  std::filesystem::path dir_;
};

TEST_F(GdalHeightmap, TagsGiveThePixelOriginSystemAndNoData) {
  const GeoTiffTags tags = readGeoTiffTags(file());
  ASSERT_TRUE(tags.georeferenced);
  EXPECT_EQ(tags.pixelWidth_m, 8.0);
  EXPECT_EQ(tags.westEdge_m, 612000.0);
  EXPECT_EQ(tags.northEdge_m, 5230000.0);
  EXPECT_EQ(tags.epsg, 25832);
  EXPECT_EQ(tags.noData, -9999.0);
}

TEST_F(GdalHeightmap, TheTerrainTakesTheFilesCellsAndLeavesNoDataOutside) {
  const Terrain t = readHeightmap(file(), 10.0, 10.0, {}, {});  // no cell size given
  EXPECT_EQ(t.grid.dx_m, 8.0);
  EXPECT_EQ(t.grid.epsg, 25832);
  EXPECT_EQ(t.grid.originEast_m, 612004.0);
  EXPECT_EQ(t.grid.originNorth_m, 5230000.0 - 19.5 * 8.0);
  ASSERT_EQ(t.outside.size(), t.grid.cellCount());
  std::size_t outside = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 30; ++x) {
      const bool corner = x < 6 && y < 5;
      EXPECT_EQ(t.isOutside(t.grid.index(x, y)), corner) << x << "," << y;
      outside += corner;
    }
  EXPECT_EQ(outside, 30u);
  // Outside heights continue the landscape (no -9999 m pit): within its range.
  for (float h : t.height_m) {
    EXPECT_GE(h, 400.0f);
    EXPECT_LE(h, 400.0f + 2.0f * 29 + 19);
  }
}

TEST_F(GdalHeightmap, AScenarioCellSizeMustAgreeWithTheFile) {
  const SourceLocation at{"s.toml", 4, "terrain.cell_size_m"};
  EXPECT_NO_THROW(readHeightmap(file(), 8.05, 8.05, {}, {}, at));  // within 1 %
  try {
    readHeightmap(file(), 10.0, 10.0, {}, {}, at);
    FAIL() << "a 10 m cell size was accepted for 8 m pixels";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 4);
    EXPECT_NE(std::string(e.what()).find("pixel size 8 x 8 m"), std::string::npos) << e.what();
  }
}

TEST_F(GdalHeightmap, AGeographicSystemIsRefused) {
  test::gdalGeoreference(dir_ / "raw.tif", dir_ / "degrees.tif", 4326, 9.0, 47.0, 0.0001, 30, 20,
                         -9999.0);
  try {
    readGeoTiffTags(dir_ / "degrees.tif");
    FAIL() << "degrees were accepted as metres";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("geographic"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace eco
