#include "render_support.hpp"

#include "sim/image_io.hpp"
#include "sim/run/run_format.hpp"
#include "sim/run/trees_file.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtx/norm.hpp>

#include "model/mesh/lod.hpp"
#include "model/strand_model.hpp"

namespace eco::test {

Species loadNamedSpecies(const std::string& name) {
  return loadSpecies(std::filesystem::path(ECOFOREST_DATA_DIR) / "species" / (name + ".toml"));
}

LibrarySpecies namedLibrarySpecies(const std::string& name) {
  return loadLibrarySpecies(std::filesystem::path(ECOFOREST_DATA_DIR) / "species" /
                            (name + ".toml"));
}

const TreeLibrary& smallLibrary() {
  static const TreeLibrary library({namedLibrarySpecies("beech"), namedLibrarySpecies("maple")},
                                   LibrarySettings{.variants = 1, .ageClasses = {0.4, 1.0}});
  return library;
}

const TreeLibrary& shapedLibrary() {
  LibrarySettings settings = LibrarySettings::shaped(true);
  settings.variants = 1;
  settings.ageClasses = {1.0};
  static const TreeLibrary library({namedLibrarySpecies("beech")}, settings);
  return library;
}

glm::vec3 linearised(const TreeVertex& v, const TreeWind& wind, double t) {
  const float sway = static_cast<float>(wind.sway_ws / kSwayBasis_ws);
  return v.position +
         sway * (static_cast<float>(std::sin(t)) * v.swaySin +
                 static_cast<float>(std::cos(t)) * v.swayCos) +
         static_cast<float>(wind.directed.x / kBendBasis_wg) * v.bendEast +
         static_cast<float>(wind.directed.y / kBendBasis_wg) * v.bendSouth;
}

std::vector<glm::vec3> cpuPositions(const Species& species, double age, const TreeWind& wind,
                                    double t, int lod) {
  const TreeMesh mesh =
      buildLod(buildStrandTree(species, windBuildOptions(species, 3, age, wind, t)), species, lod);
  std::vector<glm::vec3> positions;
  for (const MeshPart& part : mesh.parts)
    positions.insert(positions.end(), part.positions.begin(), part.positions.end());
  return positions;
}

Agreement agreement(const WindMesh& rest, const std::vector<glm::vec3>& predicted,
                    const std::vector<glm::vec3>& exact) {
  Agreement a;
  std::size_t i = 0, tip = 0;
  float highest = -1.0f;
  for (const WindPart& part : rest.parts)
    for (const TreeVertex& v : part.vertices) {
      a.rmsError += glm::distance2(predicted[i], exact[i]);
      a.rmsDisplacement += glm::distance2(v.position, exact[i]);
      if (v.position.y > highest) highest = v.position.y, tip = i;
      if (i == tip) {
        a.tipError = glm::distance(predicted[i], exact[i]);
        a.tipDisplacement = glm::distance(v.position, exact[i]);
      }
      ++i;
    }
  a.rmsError = std::sqrt(a.rmsError / i);
  a.rmsDisplacement = std::sqrt(a.rmsDisplacement / i);
  return a;
}

Terrain flatTerrain(int size, double cell_m) {
  Terrain terrain;
  terrain.grid = Grid{size, size, cell_m, cell_m};
  terrain.height_m.assign(terrain.grid.cellCount(), 100.0f);
  return terrain;
}

ImageDifference compareImages(const Image& a, const Image& b) {
  ImageDifference d;
  if (a.width != b.width || a.height != b.height) return {255.0, 255, 1.0};
  std::size_t differing = 0;
  double sum = 0.0;
  for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
    int pixelMax = 0;
    for (int c = 0; c < 3; ++c) {
      const int diff = std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c]));
      sum += diff;
      pixelMax = std::max(pixelMax, diff);
    }
    d.max = std::max(d.max, pixelMax);
    differing += pixelMax > 8;
  }
  const std::size_t pixels = a.rgba.size() / 4;
  d.mean = sum / (3.0 * pixels);
  d.differingShare = static_cast<double>(differing) / pixels;
  return d;
}

glm::vec3 meanColor(const Image& image) {
  glm::dvec3 sum(0.0);
  for (std::size_t p = 0; p < image.rgba.size(); p += 4)
    sum += glm::dvec3(image.rgba[p], image.rgba[p + 1], image.rgba[p + 2]);
  return glm::vec3(sum / (255.0 * image.rgba.size() / 4));
}

double maxBlockDifference(const Image& a, const Image& b, int block) {
  double worst = 0.0;
  for (int by = 0; by + block <= a.height; by += block)
    for (int bx = 0; bx + block <= a.width; bx += block) {
      double sum = 0.0;
      for (int y = by; y < by + block; ++y)
        for (int x = bx; x < bx + block; ++x)
          for (int c = 0; c < 3; ++c) {
            const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 4 + c;
            sum += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
          }
      worst = std::max(worst, sum / (3.0 * block * block));
    }
  return worst;
}

Image readPng(const std::filesystem::path& file) {
  return std::filesystem::exists(file) ? readColorImage(file) : Image{};
}

void writePng(const std::filesystem::path& file, const Image& image) {
  const std::vector<std::uint8_t> png = encodePng(image);
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
}

bool updatingReferences() {
  const char* value = std::getenv("ECOFOREST_UPDATE_REFERENCES");
  return value && std::string(value) == "1";
}

std::filesystem::path referenceFile(const std::string& name) {
  return std::filesystem::path(ECOFOREST_REFERENCE_DIR) / name;
}

Camera cameraAt(glm::vec3 position, float yaw_deg, float pitch_deg) {
  Camera camera;
  camera.position = position;
  camera.yaw_deg = yaw_deg;
  camera.pitch_deg = pitch_deg;
  return camera;
}

void expectSameForest(const Forest& a, const Forest& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.yaw, b.yaw);
  EXPECT_EQ(a.scaleXZ, b.scaleXZ);
  EXPECT_EQ(a.scaleY, b.scaleY);
  EXPECT_EQ(a.tint, b.tint);
  EXPECT_EQ(a.phase, b.phase);
  EXPECT_EQ(a.lean, b.lean);
  EXPECT_EQ(a.presence, b.presence);
  EXPECT_EQ(a.blendType, b.blendType);
  EXPECT_EQ(a.blendWeight, b.blendWeight);
}

TreeRow variedTree(std::uint64_t id) {
  const float height = 0.2f + static_cast<float>(id % 301) * 0.1f;
  const double angle = 0.001 * static_cast<double>(id);
  return {.id = id,
          .east_m = static_cast<double>(id % 1000),
          .north_m = static_cast<double>(id / 1000),
          .ground_m = 300,
          .age_years = static_cast<int>(id % 30),
          .height_m = height,
          .crownRadius_m = 0.2f * height,
          .crownBase_m = static_cast<float>(id % 7) * 0.1f * height,
          .vigor = static_cast<float>(id % 11) / 10.0f,
          .variantSeed = static_cast<std::uint32_t>(id * 2654435761u),
          .site = {.light = {0.5 * std::cos(angle), 0.5 * std::sin(angle)}, .wind = {0.2, 0.0}}};
}

TreeRow mostlyYoungTree(std::uint64_t id) {
  TreeRow tree = variedTree(id);
  if (id % 100 != 0) {
    tree.height_m = 0.1f + 0.01f * static_cast<float>(id % 50);
    tree.crownRadius_m = 0.3f * tree.height_m;
    tree.crownBase_m = 0.0f;
  }
  return tree;
}

RunFolder runHolding(const std::string& name, std::initializer_list<const TreeSnapshot*> snapshots,
                     SnapshotFormat format) {
  RunFolder run;
  run.dir = freshDirectory(name);
  std::filesystem::create_directories(run.dir / "trees");
  for (const TreeSnapshot* snapshot : snapshots) {
    writeTrees(RunPaths{run.dir}.snapshot(snapshot->year, format), *snapshot, format);
    run.snapshotYears.push_back(snapshot->year);
  }
  return run;
}

}  // namespace eco::test
