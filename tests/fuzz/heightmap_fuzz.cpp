// Heightmaps (sim/image_io.hpp, sim/geotiff.hpp): any image OpenImageIO reads, and a
// GeoTIFF's georeferencing tags. The first byte chooses the file's extension, which is how
// a scenario names its format.
#include "fuzz_support.hpp"
#include "sim/geotiff.hpp"
#include "sim/image_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kExtensions[] = {".png", ".tif", ".pgm", ".exr"};
  const std::string extension = kExtensions[data[0] % 4];
  const auto file =
      eco::fuzz::inputFile(eco::fuzz::asText(data + 1, size - 1), "heightmap" + extension);
  eco::fuzz::expectingInputErrors([&] { eco::readSingleChannel(file, true); });
  if (extension == ".tif") {
    eco::fuzz::expectingInputErrors([&] {
      eco::Grid grid{64, 64, 1.0, 1.0};
      eco::placeGrid(eco::readGeoTiffTags(file), grid);
    });
  }
  return 0;
}
