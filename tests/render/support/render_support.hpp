// Shared helpers of the render tests, scene and OpenGL alike: small scenes, the CPU model's
// wind for comparison, and image comparison. (gl/gl_support.hpp holds the GL context.)
#pragma once

#include <filesystem>
#include <initializer_list>
#include <memory>
#include <string>

#include "core/image.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/frame_sink.hpp"
#include "render/scene/tree_library.hpp"
#include "render/scene/wind_mesh.hpp"
#include "sim/terrain.hpp"
#include "test_files.hpp"

namespace eco::test {

Species loadNamedSpecies(const std::string& name);
// The same with its ecology, for a TreeLibrary.
LibrarySpecies namedLibrarySpecies(const std::string& name);
// A library of the named species with one variant and two age classes (young, mature):
// small enough to build in a moment. Built once per program and shared.
const TreeLibrary& smallLibrary();
// Mature beech, one variant, with shaping (LibrarySettings::shaped): one type per crown class.
const TreeLibrary& shapedLibrary();

// A flat terrain of size x size cells of `cell_m`, at altitude 100 m.
Terrain flatTerrain(int size, double cell_m);

// The linearised wind of wind_mesh.hpp, as the shader evaluates it (gust 0).
glm::vec3 linearised(const TreeVertex& v, const TreeWind& wind, double t);
// The CPU model's mesh positions of the species' tree (seed 3) under `wind` at time t.
std::vector<glm::vec3> cpuPositions(const Species& species, double age, const TreeWind& wind,
                                    double t, int lod);
// How far predicted positions are from the exact ones, against how far the exact ones moved.
struct Agreement {
  float rmsError = 0.0f;
  float rmsDisplacement = 0.0f;
  float tipError = 0.0f, tipDisplacement = 0.0f;  // the highest vertex of the rest pose
};
Agreement agreement(const WindMesh& rest, const std::vector<glm::vec3>& predicted,
                    const std::vector<glm::vec3>& exact);

// A frame sink that keeps the frames.
class CollectingSink : public FrameSink {
 public:
  void add(const Image& frame) override { frames.push_back(frame); }
  void finish() override { finished = true; }
  std::vector<Image> frames;
  bool finished = false;
};

struct ImageDifference {
  double mean = 0.0;            // mean absolute difference per channel, 0..255
  int max = 0;                  // largest absolute difference of any channel
  double differingShare = 0.0;  // share of pixels where some channel differs by more than 8
};
ImageDifference compareImages(const Image& a, const Image& b);
// Mean RGB of all pixels, 0..1.
glm::vec3 meanColor(const Image& image);
// The largest mean absolute difference (per channel, 0..255) over any block x block tile.
double maxBlockDifference(const Image& a, const Image& b, int block);

// A camera at `position` (world) looking along a bearing and pitch, in degrees.
Camera cameraAt(glm::vec3 position, float yaw_deg, float pitch_deg);

// Expects every array of two forests alike, tree by tree (gtest failures).
void expectSameForest(const Forest& a, const Forest& b);

// A snapshot's row `id` of a long run of rows of every height, crown base, vigor, age, light
// direction and variant: rows across a reader's batches that draw many types and leans.
TreeRow variedTree(std::uint64_t id);
// The same rows as in a forest, where most plants are young: one in a hundred is variedTree
// (0.2 to 30 m), the others young plants under 0.6 m.
TreeRow mostlyYoungTree(std::uint64_t id);

// A fresh run folder named `name` holding each snapshot as the year it names, in `format`.
RunFolder runHolding(const std::string& name, std::initializer_list<const TreeSnapshot*> snapshots,
                     SnapshotFormat format);

// Reads and writes reference PNGs in tests/render/reference/. Set ECOFOREST_UPDATE_REFERENCES=1
// to rewrite them from the current output.
Image readPng(const std::filesystem::path& file);
void writePng(const std::filesystem::path& file, const Image& image);
bool updatingReferences();
std::filesystem::path referenceFile(const std::string& name);

}  // namespace eco::test
