#include "sim/terrain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/names.hpp"
#include "core/random.hpp"
#include "sim/geotiff.hpp"
#include "sim/image_io.hpp"
#include "sim/terrain_mesh.hpp"

namespace eco {

float Terrain::altitudeAt(double east_m, double north_m) const {
  return altitudeOnTriangles(*this, east_m, north_m);
}

Field maskOutside(const Terrain& terrain, Field field) {
  for (std::size_t i = 0; i < terrain.outside.size(); ++i)
    if (terrain.outside[i]) field[i] = std::numeric_limits<float>::quiet_NaN();
  return field;
}

namespace {

bool isTiff(const std::filesystem::path& file) {
  const std::string extension = file.extension().string();
  return sameNameIgnoringCase(extension, ".tif") || sameNameIgnoringCase(extension, ".tiff");
}

// The outside cells take heights that continue the terrain: layer by layer from the
// landscape's edge, each the mean of its neighbours already known.
void fillOutside(Terrain& terrain, const std::filesystem::path& file) {
  const Grid& g = terrain.grid;
  std::vector<std::uint8_t> known(g.cellCount());
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < known.size(); ++i) known[i] = !terrain.isOutside(i);
  if (std::find(known.begin(), known.end(), 1) == known.end())
    throw InputError({file.string(), 0, ""}, "every pixel of the heightmap is no-data");
  const std::array<std::pair<int, int>, 4> steps{{{-1, 0}, {1, 0}, {0, -1}, {0, 1}}};
  for (bool grew = true; grew;) {
    grew = false;
    front.clear();
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width; ++x) {
        if (known[g.index(x, y)]) continue;
        double sum = 0.0;
        int count = 0;
        for (auto [ox, oy] : steps)
          if (g.contains(x + ox, y + oy) && known[g.index(x + ox, y + oy)])
            sum += terrain.heightAt(x + ox, y + oy), ++count;
        if (count == 0) continue;
        terrain.height_m[g.index(x, y)] = static_cast<float>(sum / count);
        front.push_back(g.index(x, y));
      }
    // A layer becomes known only once it is complete, so the fill does not depend on the
    // order cells are visited in.
    for (std::size_t i : front) known[i] = 1;
    grew = !front.empty();
  }
}

}  // namespace

Terrain readHeightmap(const std::filesystem::path& file, double dx_m, double dy_m,
                      std::optional<double> heightMin_m, std::optional<double> heightMax_m,
                      const std::optional<SourceLocation>& cellSizeAt) {
  const GeoTiffTags tags = isTiff(file) ? readGeoTiffTags(file) : GeoTiffTags{};
  const bool nanNoData = tags.noData && std::isnan(*tags.noData);
  SingleChannelImage image = readSingleChannel(file, nanNoData);
  Terrain terrain;
  terrain.grid = Grid{image.width, image.height, dx_m, dy_m};
  if (tags.georeferenced) {
    for (auto [given, fromFile] : {std::pair{dx_m, tags.pixelWidth_m}, {dy_m, tags.pixelHeight_m}})
      if (cellSizeAt && std::abs(given - fromFile) > 0.01 * fromFile)
        throw InputError(
            *cellSizeAt,
            fmt::format("the scenario's cell size {:g} m disagrees with the "
                        "pixel size {:g} x {:g} m of {}: drop cell_size_m to use "
                        "the file's",
                        given, tags.pixelWidth_m, tags.pixelHeight_m, file.filename().string()));
    placeGrid(tags, terrain.grid);
  }
  terrain.height_m = std::move(image.values);
  if (tags.noData) {
    const float noData = static_cast<float>(*tags.noData);
    terrain.outside.assign(terrain.height_m.size(), 0);
    for (std::size_t i = 0; i < terrain.height_m.size(); ++i)
      terrain.outside[i] =
          nanNoData ? std::isnan(terrain.height_m[i]) : terrain.height_m[i] == noData;
    if (std::find(terrain.outside.begin(), terrain.outside.end(), 1) == terrain.outside.end())
      terrain.outside.clear();
  }
  if (heightMin_m && heightMax_m) {
    // Integer images: 0 .. maximum of the file's type; float images: 0 .. 1.
    const double top = image.typeMax;
    const double lo = *heightMin_m, span = *heightMax_m - *heightMin_m;
    for (float& h : terrain.height_m) h = static_cast<float>(lo + span * (h / top));
  }
  if (!terrain.outside.empty()) fillOutside(terrain, file);
  return terrain;
}

Terrain generateMidpoint(const GeneratedTerrain& settings, double dx_m, double dy_m, double base_m,
                         std::uint64_t seed) {
  const int n = settings.size;
  ECO_ASSERT(n >= 3 && ((n - 1) & (n - 2)) == 0, "size=" << n);
  Terrain terrain;
  terrain.grid = Grid{n, n, dx_m, dy_m};
  Field& h = terrain.height_m;
  h.assign(terrain.grid.cellCount(), 0.0f);
  auto offset = [&](int x, int y, double amplitude) {
    Rng rng(streamKey(seed, static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y),
                      purpose("midpoint")));
    return static_cast<float>(amplitude * rng.uniform(-1.0, 1.0));
  };
  auto at = [&](int x, int y) -> float& { return h[terrain.grid.index(x, y)]; };
  for (int x : {0, n - 1})
    for (int y : {0, n - 1}) at(x, y) = offset(x, y, 1.0);
  double amplitude = 1.0;
  for (int step = n - 1; step > 1; step /= 2) {
    const int half = step / 2;
    amplitude *= settings.roughness;
    // Diamond: the centre of every square is its corners' mean plus a displacement.
    for (int y = half; y < n; y += step)
      for (int x = half; x < n; x += step)
        at(x, y) = 0.25f * (at(x - half, y - half) + at(x + half, y - half) +
                            at(x - half, y + half) + at(x + half, y + half)) +
                   offset(x, y, amplitude);
    // Square: every edge midpoint is the mean of its (up to four) diamond neighbours.
    for (int y = 0; y < n; y += half)
      for (int x = (y / half) % 2 == 0 ? half : 0; x < n; x += step) {
        float sum = 0.0f;
        int count = 0;
        for (auto [ox, oy] : {std::pair{-half, 0}, {half, 0}, {0, -half}, {0, half}})
          if (terrain.grid.contains(x + ox, y + oy)) sum += at(x + ox, y + oy), ++count;
        at(x, y) = sum / static_cast<float>(count) + offset(x, y, amplitude);
      }
  }
  auto [lo, hi] = std::minmax_element(h.begin(), h.end());
  const float low = *lo, span = std::max(*hi - *lo, 1e-6f);
  for (float& v : h) v = static_cast<float>(base_m + settings.relief_m * (v - low) / span);
  return terrain;
}

Terrain loadTerrain(const Scenario& scenario) {
  const TerrainSpec& spec = scenario.terrain;
  Terrain terrain = spec.generate
                        ? generateMidpoint(*spec.generate, spec.cellDx_m, spec.cellDy_m,
                                           spec.baseAltitude_m, scenario.seed)
                        : readHeightmap(*spec.heightmap, spec.cellDx_m, spec.cellDy_m,
                                        spec.heightMin_m, spec.heightMax_m, spec.cellSizeAt);
  terrain.closedDepressions = spec.closedDepressions;
  return terrain;
}

void writeHeightmap16(const Terrain& terrain, const std::filesystem::path& file, double lo_m,
                      double hi_m) {
  std::vector<std::uint16_t> values(terrain.height_m.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    double t = std::clamp((terrain.height_m[i] - lo_m) / (hi_m - lo_m), 0.0, 1.0);
    values[i] = static_cast<std::uint16_t>(std::lround(t * 65535.0));
  }
  writeUint16Image(file, terrain.grid.width, terrain.grid.height, values);
}

}  // namespace eco
