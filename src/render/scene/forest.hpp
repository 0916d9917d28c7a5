// The trees of one frame as parallel arrays: which library type draws each, where it stands
// and how it is turned, scaled and tinted. Built from a run's snapshot or, for a scenario
// without a run, from a demo planting.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "model/tree_shaping.hpp"
#include "render/scene/tree_library.hpp"
#include "sim/run/run_folder.hpp"
#include "sim/terrain.hpp"

namespace eco {

struct Forest {
  std::vector<std::int32_t> type;
  std::vector<glm::vec3> position;  // world position of the stem base
  std::vector<float> yaw;           // radians
  std::vector<float> scaleXZ;       // horizontal scale of the type's mesh
  std::vector<float> scaleY;        // vertical scale
  std::vector<glm::vec3> tint;      // multiplies the albedo
  std::vector<float> phase;         // wind time offset, so that trees sway out of step
  // The site's lean (model/tree_shaping.hpp) as the shaders draw it: multiples of the type's
  // bend bases (x bendEast, y bendSouth; LeanResponse::basesFor). add() sets 0.
  std::vector<glm::vec2> lean;
  // Growth between snapshots (time-lapse): the share of the tree's pixels drawn (a seedling
  // appearing, a dead tree fading), and a second type it is cross-fading into (the next age
  // class) with that type's share. add() sets 1, -1, 0: a whole tree of one type.
  std::vector<float> presence;
  std::vector<std::int32_t> blendType;
  std::vector<float> blendWeight;

  std::size_t size() const { return type.size(); }
  // The bytes its arrays hold, room reserved included.
  std::size_t memoryBytes() const;
  void reserve(std::size_t n);
  // Appends tree i of `from`, every array alike (a subset of a forest: species shown).
  void append(const Forest& from, std::size_t i);
  // One tree exactly as its type was built: not turned, scaled or tinted (the designer).
  void addAsBuilt(int typeIndex, glm::vec3 base);
  // One plant, drawn by `typeIndex` at its height and crown radius.
  void add(const TreeLibrary& library, int typeIndex, glm::vec3 base, float height_m,
           float crownRadius_m, float vigor, std::uint64_t individual);
  // The same into place i, fresh from resize, of a forest resized to hold it (places filled
  // side by side). resize gives new places an upright, whole tree of type 0, unscaled.
  void resize(std::size_t n);
  void place(std::size_t i, const TreeLibrary& library, int typeIndex, glm::vec3 base,
             float height_m, float crownRadius_m, float vigor, std::uint64_t individual);
};

// The sphere around tree i as drawn: its type's bounds (TreeType::bounds) turned by its yaw,
// scaled and placed; (centre, radius) in world metres.
glm::vec4 drawnBounds(const Forest& forest, std::size_t i, const TreeType& type);

// The library types a forest draws (each tree's type and the one it blends into), each once
// in ascending order.
std::vector<int> typesOf(const Forest& forest);
// Builds them side by side (TreeLibrary::build): what the forests made here do before they
// are drawn, so that no type is built on its own in a draw.
void buildTypesOf(const Forest& forest, const TreeLibrary& library);

// The library's species index of each of the snapshot's species names; an InputError
// (at `where`) names a species the library does not have.
std::vector<int> librarySpeciesOf(const TreeSnapshot& snapshot, const TreeLibrary& library,
                                  const std::string& where);
// The same for a snapshot read a batch of rows at a time (TreeBatch), whose batches name
// more species as their rows come: each new name is looked up once.
class SpeciesNumbering {
 public:
  SpeciesNumbering(const TreeLibrary& library, std::string where)
      : library_(library), where_(std::move(where)) {}
  // The library's species of each of `names` (the batch's species names so far).
  const std::vector<int>& of(const std::vector<std::string>& names);

 private:
  const TreeLibrary& library_;
  std::string where_;
  std::vector<int> numbered_;
};

// Every plant of a snapshot; species are matched to the library by name. An InputError
// names a species the library does not have. In a library with shaping (LibrarySettings),
// each tree is drawn by its crown class and leans as its site says.
Forest forestFromSnapshot(const TreeSnapshot& snapshot, const TreeLibrary& library,
                          const std::string& where);
// The same forest from a run's snapshot of `year`, built a batch of rows at a time as the
// file is read (readSnapshotInBatches): a landscape's hundred million plants hold their 64
// bytes each of the forest, never the rows' 88 besides. Only the rows `keep` keeps, if given.
Forest forestFromRun(const RunFolder& run, int year, const TreeLibrary& library,
                     const TreeFilter& keep = {});
// The same snapshot a batch of rows at a time, each batch's trees placed into a forest of
// their own and handed to `each`, which keeps what it needs of them: a still needs few of a
// landscape's hundred million plants (render/scene/seen_forest.hpp).
void forEachForestBatch(const RunFolder& run, int year, const TreeLibrary& library,
                        const std::function<void(const Forest&)>& each);

// The library type that draws a snapshot's tree of the library's species `species`: its
// variant by its seed, its age class by its height, its crown class by its clear bole.
int drawnType(const TreeRow& tree, int species, const TreeLibrary& library);

// The model's shaping of a snapshot's tree as `library` draws it: its light and wind turned
// into the tree frame (east, south), and the share of its height below the crown base;
// neutral in a library without shaping.
SiteShaping siteShapingOf(const TreeRow& tree, const TreeLibrary& library);
// The lean of a tree of `type` on `site` as the shaders draw it (Forest::lean).
glm::vec2 drawnLean(const TreeLibrary& library, int type, const SiteShaping& site);
// The same from the site's lean (shapingLean) kept as floats: a tree's lean for any type.
glm::vec2 drawnLean(const TreeLibrary& library, int type, glm::vec2 siteLean);

// `count` trees spread uniformly over the terrain with species drawn evenly and heights from
// seedlings to mature (the terrain-with-trees view of a scenario without a run).
Forest demoForest(const Terrain& terrain, const TreeLibrary& library, std::size_t count,
                  std::uint64_t seed);

}  // namespace eco
