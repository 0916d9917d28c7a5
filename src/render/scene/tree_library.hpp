// The trees a renderer can draw: for each species a few variants (seeds) times a few age
// classes (times a few crown classes, with shaping), each built once by the model with its
// three LODs and wind bases. A plant of a run is drawn as the type of its species, variant
// (its variant seed), nearest age class and crown class, scaled to its height and crown.
// A type's meshes are built when it is first used: a young run draws an eighth of the
// types, and the meshes are most of the time it takes to open a run.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec4.hpp>

#include "model/species.hpp"
#include "render/scene/wind_mesh.hpp"
#include "sim/ecology/species_ecology.hpp"
#include "sim/scenario.hpp"

namespace eco {

// A species as the renderer draws it: its tree model and, for a species that grows in an
// ecosystem, the [ecology] of its file (how tall it grows, how small a seedling is).
struct LibrarySpecies {
  Species model;
  std::optional<Ecology> ecology;
};
// The species file's tree model and ecology.
LibrarySpecies loadLibrarySpecies(const std::filesystem::path& file);
// Those of each [[species]] of a scenario, in its order.
std::vector<LibrarySpecies> loadLibrarySpecies(const Scenario& scenario);

// The crown classes of a library with shaping: the share of the height below the crown
// base whose side branches are pruned (docs/rendering.md, "Trees shaped by their site").
inline const std::vector<double> kShapedClearBoleClasses{0.0, 0.3, 0.55};

struct LibrarySettings {
  int variants = 3;
  std::vector<double> ageClasses{0.15, 0.4, 0.7, 1.0};  // the model's age parameter
  // Trees shaped by their site: each leans as its light and wind say (through the bend
  // bases), and is drawn by the crown class nearest its own clear bole. Without, every
  // tree is the species' own, open-grown and upright (one crown class, 0).
  bool shaping = false;
  std::vector<double> clearBoleClasses{0.0};
  static LibrarySettings shaped(bool on) {
    LibrarySettings settings;
    settings.shaping = on;
    if (on) settings.clearBoleClasses = kShapedClearBoleClasses;
    return settings;
  }
};

// One type of a library. Its grid place, seed and sizes are there from the start; its
// bounds, envelope, meshes and lean response once it is built (TreeLibrary::type()).
struct TreeType {
  int species = 0;
  int variant = 0;
  int ageClass = 0;
  int crownClass = 0;
  std::uint64_t seed = 1;
  double age = 1.0;
  double clearBole = 0.0;  // share of the height below the crown base, pruned
  float height_m = 0.0f;   // of the rest mesh
  float crownRadius_m = 0.0f;
  glm::vec4 bounds{0.0f};  // centre (tree frame) and radius of a sphere around every LOD
  // The largest horizontal reach of LOD0 from the stem axis in each of kEnvelopeBins equal
  // slices of the height (metres, tree frame): the trunk near the ground, the crown above,
  // for keeping a camera clear of the tree as drawn.
  static constexpr int kEnvelopeBins = 16;
  std::array<float, kEnvelopeBins> envelope_m{};
  WindLods meshes;
  // How its bend bases draw a site's lean (measured in a library with shaping only).
  LeanResponse leanResponse;
  // The type whose impostor frames this one shows (ForestRenderer bakes that type's only).
  int impostorSource = 0;
};

// Height, crown, bounds and envelope of a type from its rest skeleton's measures and its
// meshes.
void measureType(TreeType& type, const SkeletonMeasures& rest);

class TreeLibrary {
 public:
  TreeLibrary(std::vector<LibrarySpecies> species, const LibrarySettings& settings);
  // Types the caller built, each its own impostor source (the designer's preview, whose
  // trees are not a grid of variants and ages): typeIndex(), typeFor() and blendFor() are
  // for the grid above and must not be called. setType() replaces one as the user edits.
  TreeLibrary(std::vector<Species> species, std::vector<TreeType> types);
  void setType(int index, TreeType type);

  const std::vector<Species>& species() const { return species_; }
  // The largest height a species reaches (its growth curve's maximum, or its mature tree).
  float maxHeight_m(int species) const { return maxHeight_m_[species]; }
  // The height of a seedling in its first year.
  float seedlingHeight_m(int species) const { return seedlingHeight_m_[species]; }
  int typeCount() const { return static_cast<int>(types_.size()); }
  // The type, built on its first use: from any thread, each type once, the same whatever
  // the order.
  const TreeType& type(int index) const;
  // Builds these types (a forest's: typesOf) side by side; built ones are skipped.
  void build(std::span<const int> types) const;
  // How many types are built (all in a library of given types).
  int builtTypeCount() const { return grid_ ? builtCount_.load() : typeCount(); }
  // A type's height, crown radius and impostor source, without building it.
  float typeHeight_m(int index) const { return types_[index].height_m; }
  float typeCrownRadius_m(int index) const { return types_[index].crownRadius_m; }
  int impostorSource(int index) const { return types_[index].impostorSource; }
  const LibrarySettings& settings() const { return settings_; }
  int typeIndex(int species, int variant, int ageClass, int crownClass = 0) const;
  // The type that draws a plant of this species, variant seed and height: its species'
  // variant (seed modulo the variants) at the age class whose tree is nearest in height
  // relative to the species' largest (compared in logarithms), in the crown class nearest
  // its clear bole (the share of its height below the crown base).
  int typeFor(int species, std::uint64_t variantSeed, float height_m, float speciesMaxHeight_m,
              double clearBole = 0.0) const;
  int crownClassFor(double clearBole) const;
  // The same as two neighbouring age classes blended by relative height (in logarithms), for
  // growth that changes class without a jump: `type` is the younger class, `blendType` the
  // older (or -1 outside the classes' range) and `blendWeight` the older's share.
  struct Blend {
    int type = 0;
    int blendType = -1;
    float blendWeight = 0.0f;
  };
  Blend blendFor(int species, std::uint64_t variantSeed, float height_m, float speciesMaxHeight_m,
                 double clearBole = 0.0) const;
  // The seed of a variant: the model's individual of that variant.
  static std::uint64_t variantSeed(int variant) {
    return 1 + 7919 * static_cast<std::uint64_t>(variant);
  }

 private:
  // Its meshes, lean response, bounds and envelope.
  void buildType(TreeType& type) const;

  std::vector<Species> species_;
  std::vector<float> maxHeight_m_, seedlingHeight_m_;
  LibrarySettings settings_;
  bool grid_ = true;  // types are species x variants x age classes
  // A grid type's meshes are filled in by type() on first use, once (`built_`); a library of
  // given types has every type built.
  mutable std::vector<TreeType> types_;
  std::unique_ptr<std::once_flag[]> built_;
  mutable std::atomic<int> builtCount_{0};
};

}  // namespace eco
