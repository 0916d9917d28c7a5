#include "sim/geotiff.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <geotiff/geokeys.h>
#include <geotiff/geotiff.h>
#include <geotiff/geovalues.h>
#include <geotiff/xtiffio.h>
#include <tiffio.h>
#include <tiffio.hxx>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace eco {
namespace {

// GDAL's no-data tag: an ASCII number. libtiff does not know it, so it is registered
// beside the GeoTIFF tags (XTIFFInitialize) for reading and writing.
constexpr ttag_t kGdalNoDataTag = 42113;

TIFFExtendProc previousExtender = nullptr;

void addGdalTags(TIFF* tiff) {
  static const TIFFFieldInfo noData[] = {{kGdalNoDataTag, -1, -1, TIFF_ASCII, FIELD_CUSTOM, 1, 0,
                                          const_cast<char*>("GDALNoDataValue")}};
  TIFFMergeFieldInfo(tiff, noData, 1);
  if (previousExtender) previousExtender(tiff);
}

void registerTags() {
  static std::once_flag once;
  std::call_once(once, [] {
    XTIFFInitialize();
    previousExtender = TIFFSetTagExtender(addGdalTags);
    // libtiff's warnings (unknown tags of other writers) and messages are not the user's
    // concern here: a file it cannot read is reported as an InputError.
    TIFFSetWarningHandler(nullptr);
    TIFFSetErrorHandler(nullptr);
  });
}

struct GtifCloser {
  void operator()(GTIF* gtif) const { GTIFFree(gtif); }
};
struct TiffCloser {
  void operator()(TIFF* tiff) const { XTIFFClose(tiff); }
};

unsigned short shortKey(GTIF* gtif, geokey_t key) {
  unsigned short value = 0;
  return GTIFKeyGetSHORT(gtif, key, &value, 0, 1) == 1 ? value : 0;
}

}  // namespace

GeoTiffTags readGeoTiffTags(const std::filesystem::path& file) {
  registerTags();
  std::unique_ptr<TIFF, TiffCloser> tiff(XTIFFOpen(file.c_str(), "r"));
  if (!tiff) throw InputError({file.string(), 0, ""}, "not a TIFF file libtiff can read");
  const std::string where = file.string();
  GeoTiffTags tags;
  std::uint16_t count = 0;
  double* scale = nullptr;
  double* ties = nullptr;
  std::uint16_t tieCount = 0;
  const bool hasScale =
      TIFFGetField(tiff.get(), TIFFTAG_GEOPIXELSCALE, &count, &scale) && count >= 2;
  const bool hasTie =
      TIFFGetField(tiff.get(), TIFFTAG_GEOTIEPOINTS, &tieCount, &ties) && tieCount >= 6;
  char* noData = nullptr;
  if (TIFFGetField(tiff.get(), kGdalNoDataTag, &noData) && noData) {
    char* end = nullptr;
    const double value = std::strtod(noData, &end);
    if (end == noData)
      throw InputError({where, 0, "GDAL_NODATA"}, fmt::format("not a number: '{}'", noData));
    tags.noData = value;
  }
  if (!hasScale || !hasTie) return tags;
  if (!(std::isfinite(scale[0]) && std::isfinite(scale[1]) && scale[0] > 0.0 && scale[1] > 0.0))
    throw InputError({where, 0, "ModelPixelScale"},
                     fmt::format("pixel size {} x {} is not positive", scale[0], scale[1]));
  if (!(std::isfinite(ties[3]) && std::isfinite(ties[4])))
    throw InputError({where, 0, "ModelTiepoint"}, "the tie point is not finite");
  tags.georeferenced = true;
  tags.pixelWidth_m = scale[0];
  tags.pixelHeight_m = scale[1];

  std::unique_ptr<GTIF, GtifCloser> gtif(GTIFNew(tiff.get()));
  bool pixelIsPoint = false;
  if (gtif) {
    const unsigned short model = shortKey(gtif.get(), GTModelTypeGeoKey);
    if (model == ModelTypeGeographic)
      throw InputError({where, 0, "GTModelTypeGeoKey"},
                       "the heightmap is in a geographic coordinate system (degrees): "
                       "reproject it to a projected system in metres (e.g. UTM)");
    const unsigned short units = shortKey(gtif.get(), ProjLinearUnitsGeoKey);
    if (units != 0 && units != Linear_Meter)
      throw InputError({where, 0, "ProjLinearUnitsGeoKey"},
                       fmt::format("linear unit {} is not the metre (EPSG 9001): "
                                   "ecoforest's map coordinates are metres",
                                   units));
    const unsigned short system = shortKey(gtif.get(), ProjectedCSTypeGeoKey);
    if (system != 0 && system != KvUserDefined) tags.epsg = system;
    pixelIsPoint = shortKey(gtif.get(), GTRasterTypeGeoKey) == RasterPixelIsPoint;
  }
  // The tie point (i, j, k, X, Y, Z): raster position (i, j) is at (X, Y), where a position
  // is a pixel's corner (pixel is area, the default) or its centre (pixel is point).
  const double shift = pixelIsPoint ? 0.5 : 0.0;
  tags.westEdge_m = ties[3] - (ties[0] + shift) * scale[0];
  tags.northEdge_m = ties[4] + (ties[1] + shift) * scale[1];
  return tags;
}

void placeGrid(const GeoTiffTags& tags, Grid& grid) {
  grid.dx_m = tags.pixelWidth_m;
  grid.dy_m = tags.pixelHeight_m;
  grid.originEast_m = tags.westEdge_m + 0.5 * grid.dx_m;
  grid.originNorth_m = tags.northEdge_m - (grid.height - 0.5) * grid.dy_m;
  grid.epsg = tags.epsg;
}

void writeGeoTiff(const std::filesystem::path& file, const Grid& grid, const Field& values) {
  ECO_ASSERT(values.size() == grid.cellCount(), file);
  registerTags();
  std::ostringstream bytes;
  {
    std::unique_ptr<TIFF, TiffCloser> tiff(TIFFStreamOpen(file.filename().c_str(), &bytes));
    if (!tiff) throw InternalError("libtiff could not start " + file.string());
    TIFF* t = tiff.get();
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, static_cast<std::uint32_t>(grid.width));
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(grid.height));
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1);
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 32);
    TIFFSetField(t, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(t, TIFFTAG_PREDICTOR, PREDICTOR_FLOATINGPOINT);
    TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, 16);
    TIFFSetField(t, TIFFTAG_SOFTWARE, "ecoforest");
    const double scale[3] = {grid.dx_m, grid.dy_m, 0.0};
    const double west = grid.originEast_m - 0.5 * grid.dx_m;
    const double north = grid.originNorth_m + (grid.height - 0.5) * grid.dy_m;
    const double tie[6] = {0.0, 0.0, 0.0, west, north, 0.0};
    TIFFSetField(t, TIFFTAG_GEOPIXELSCALE, 3, scale);
    TIFFSetField(t, TIFFTAG_GEOTIEPOINTS, 6, tie);
    TIFFSetField(t, kGdalNoDataTag, "nan");
    std::unique_ptr<GTIF, GtifCloser> gtif(GTIFNew(t));
    if (!gtif) throw InternalError("libgeotiff could not start " + file.string());
    GTIFKeySet(gtif.get(), GTRasterTypeGeoKey, TYPE_SHORT, 1, RasterPixelIsArea);
    GTIFKeySet(gtif.get(), GTModelTypeGeoKey, TYPE_SHORT, 1, ModelTypeProjected);
    if (grid.epsg != 0) {
      GTIFKeySet(gtif.get(), ProjectedCSTypeGeoKey, TYPE_SHORT, 1, grid.epsg);
    } else {
      // Local metres: a projected system of no known kind.
      GTIFKeySet(gtif.get(), ProjectedCSTypeGeoKey, TYPE_SHORT, 1, KvUserDefined);
      GTIFKeySet(gtif.get(), ProjLinearUnitsGeoKey, TYPE_SHORT, 1, Linear_Meter);
    }
    GTIFWriteKeys(gtif.get());
    std::vector<float> row(static_cast<std::size_t>(grid.width));
    for (int y = 0; y < grid.height; ++y) {
      // A copy: the floating-point predictor encodes the row it is given in place.
      std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(grid.index(0, y)), grid.width,
                  row.begin());
      if (TIFFWriteScanline(t, row.data(), static_cast<std::uint32_t>(y), 0) < 0)
        throw InternalError("libtiff could not write a row of " + file.string());
    }
  }
  AtomicFile out(file);
  out.write(bytes.view());
  out.commit();
}

void writeImageGeoreference(const std::filesystem::path& image, const Grid& grid) {
  std::string extension = image.extension().string();  // .png -> .pgw, .tif -> .tfw
  const std::string world =
      extension.size() == 4 ? fmt::format(".{}{}w", extension[1], extension[3]) : ".wld";
  const double westCentre = grid.originEast_m;
  const double northCentre = grid.originNorth_m + (grid.height - 1) * grid.dy_m;
  AtomicFile out(std::filesystem::path(image).replace_extension(world));
  out.write(fmt::format("{:.10g}\n0\n0\n{:.10g}\n{:.10f}\n{:.10f}\n", grid.dx_m, -grid.dy_m,
                        westCentre, northCentre));
  out.commit();
  if (grid.epsg == 0) return;
  AtomicFile aux(image.string() + ".aux.xml");
  aux.write(
      fmt::format("<PAMDataset>\n  <SRS dataAxisToSRSAxisMapping=\"1,2\">EPSG:{}</SRS>\n"
                  "</PAMDataset>\n",
                  grid.epsg));
  aux.commit();
}

}  // namespace eco
