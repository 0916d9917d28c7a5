// Shared helpers of the render tests: one headless context per test program, small scenes
// and image comparison.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "core/image.hpp"
#include "render/forest.hpp"
#include "render/gl_context.hpp"
#include "render/tree_library.hpp"
#include "sim/terrain.hpp"
#include "test_files.hpp"

namespace eco::test {

// Makes the process's headless OpenGL context current (created on first use).
void useHeadlessGl();

Species loadNamedSpecies(const std::string& name);
// The same with its ecology, for a TreeLibrary.
LibrarySpecies namedLibrarySpecies(const std::string& name);
// A library of the named species with one variant and two age classes (young, mature):
// small enough to build in a moment. Built once per program and shared.
const TreeLibrary& smallLibrary();

// A flat terrain of size x size cells of `cell_m`, at altitude 100 m.
Terrain flatTerrain(int size, double cell_m);

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

// Reads and writes reference PNGs in tests/render/reference/. Set ECOFOREST_UPDATE_REFERENCES=1
// to rewrite them from the current output.
Image readPng(const std::filesystem::path& file);
void writePng(const std::filesystem::path& file, const Image& image);
bool updatingReferences();
std::filesystem::path referenceFile(const std::string& name);

}  // namespace eco::test
