#include "render/scene/forest.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include <tbb/parallel_for.h>
#include <glm/common.hpp>

#include "core/error.hpp"
#include "core/random.hpp"
#include "render/scene/camera.hpp"

namespace eco {

void Forest::reserve(std::size_t n) {
  type.reserve(n);
  position.reserve(n);
  yaw.reserve(n);
  scaleXZ.reserve(n);
  scaleY.reserve(n);
  tint.reserve(n);
  phase.reserve(n);
  lean.reserve(n);
  presence.reserve(n);
  blendType.reserve(n);
  blendWeight.reserve(n);
}

std::size_t Forest::memoryBytes() const {
  auto bytes = [](const auto& array) { return array.capacity() * sizeof(array[0]); };
  return bytes(type) + bytes(position) + bytes(yaw) + bytes(scaleXZ) + bytes(scaleY) + bytes(tint) +
         bytes(phase) + bytes(lean) + bytes(presence) + bytes(blendType) + bytes(blendWeight);
}

void Forest::append(const Forest& from, std::size_t i) {
  type.push_back(from.type[i]);
  position.push_back(from.position[i]);
  yaw.push_back(from.yaw[i]);
  scaleXZ.push_back(from.scaleXZ[i]);
  scaleY.push_back(from.scaleY[i]);
  tint.push_back(from.tint[i]);
  phase.push_back(from.phase[i]);
  lean.push_back(from.lean[i]);
  presence.push_back(from.presence[i]);
  blendType.push_back(from.blendType[i]);
  blendWeight.push_back(from.blendWeight[i]);
}

void Forest::addAsBuilt(int typeIndex, glm::vec3 base) {
  resize(size() + 1);  // not turned, scaled or tinted: resize's values
  type.back() = typeIndex;
  position.back() = base;
}

void Forest::resize(std::size_t n) {
  type.resize(n, 0);
  position.resize(n, glm::vec3(0.0f));
  yaw.resize(n, 0.0f);
  scaleXZ.resize(n, 1.0f);
  scaleY.resize(n, 1.0f);
  tint.resize(n, glm::vec3(1.0f));
  phase.resize(n, 0.0f);
  lean.resize(n, glm::vec2(0.0f));
  presence.resize(n, 1.0f);
  blendType.resize(n, -1);
  blendWeight.resize(n, 0.0f);
}

void Forest::add(const TreeLibrary& library, int typeIndex, glm::vec3 base, float height_m,
                 float crownRadius_m, float vigor, std::uint64_t individual) {
  resize(size() + 1);
  place(size() - 1, library, typeIndex, base, height_m, crownRadius_m, vigor, individual);
}

void Forest::place(std::size_t i, const TreeLibrary& library, int typeIndex, glm::vec3 base,
                   float height_m, float crownRadius_m, float vigor, std::uint64_t individual) {
  Rng rng(streamKey(individual, purpose("render.instance")));
  const float vertical = std::max(height_m, 0.01f) / library.typeHeight_m(typeIndex);
  // The crown may be narrower or wider than the type's (shade, open growth), within limits
  // that keep the mesh believable.
  const float widthRatio =
      crownRadius_m > 0.0f
          ? std::clamp(crownRadius_m / (library.typeCrownRadius_m(typeIndex) * vertical), 0.7f,
                       1.4f)
          : 1.0f;
  type[i] = typeIndex;
  position[i] = base;
  yaw[i] = static_cast<float>(rng.uniform(0.0, 2.0 * std::numbers::pi));
  scaleY[i] = vertical;
  scaleXZ[i] = vertical * widthRatio;
  // Weak trees pale toward yellow; each tree varies a little in brightness.
  const float brightness = static_cast<float>(rng.uniform(0.9, 1.1));
  const glm::vec3 stressed(1.15f, 1.05f, 0.6f);
  tint[i] = brightness * glm::mix(stressed, glm::vec3(1.0f), std::clamp(vigor, 0.0f, 1.0f));
  phase[i] = static_cast<float>(rng.uniform(0.0, 2.0 * std::numbers::pi));
  // lean, presence and the blend keep resize's values: upright, whole, one type.
}

namespace {

// Each type of `types` and `blends` (a blend's -1 none) once, in ascending order: a mark a
// type, as a landscape's forest holds a hundred million trees of a few hundred types.
std::vector<int> typesIn(std::span<const std::int32_t> types,
                         std::span<const std::int32_t> blends) {
  std::int32_t most = -1;
  for (const std::int32_t t : types) most = std::max(most, t);
  for (const std::int32_t t : blends) most = std::max(most, t);
  std::vector<char> drawn(static_cast<std::size_t>(most + 1), 0);
  for (const std::int32_t t : types) drawn[static_cast<std::size_t>(t)] = 1;
  for (const std::int32_t t : blends)
    if (t >= 0) drawn[static_cast<std::size_t>(t)] = 1;
  std::vector<int> listed;
  for (std::size_t t = 0; t < drawn.size(); ++t)
    if (drawn[t]) listed.push_back(static_cast<int>(t));
  return listed;
}

int librarySpeciesNamed(const std::string& name, const TreeLibrary& library,
                        const std::string& where) {
  const auto& all = library.species();
  auto found =
      std::find_if(all.begin(), all.end(), [&](const Species& s) { return s.name == name; });
  if (found == all.end())
    throw InputError({where, 0, "species"},
                     "the trees name species '" + name + "', which the scenario does not have");
  return static_cast<int>(found - all.begin());
}

// Snapshot rows drawn into the forest's places from `start` on, each tree on its own, side
// by side: its type and placement, then, with the types built, its lean (which reads the
// built types' responses).
void placeRows(Forest& forest, std::size_t start, std::span<const TreeRow> rows,
               const std::vector<int>& librarySpecies, const TreeLibrary& library) {
  tbb::parallel_for(std::size_t{0}, rows.size(), [&](std::size_t i) {
    const TreeRow& tree = rows[i];
    const int type = drawnType(tree, librarySpecies[tree.species], library);
    forest.place(start + i, library, type, worldFromMap(tree.east_m, tree.north_m, tree.ground_m),
                 tree.height_m, tree.crownRadius_m, tree.vigor, tree.variantSeed ^ tree.id);
  });
  library.build(typesIn(std::span(forest.type).subspan(start, rows.size()),
                        std::span(forest.blendType).subspan(start, rows.size())));
  tbb::parallel_for(std::size_t{0}, rows.size(), [&](std::size_t i) {
    forest.lean[start + i] =
        drawnLean(library, forest.type[start + i], siteShapingOf(rows[i], library));
  });
}

}  // namespace

int drawnType(const TreeRow& tree, int species, const TreeLibrary& library) {
  return library.typeFor(species, tree.variantSeed, tree.height_m, library.maxHeight_m(species),
                         siteShapingOf(tree, library).clearBole);
}

glm::vec4 drawnBounds(const Forest& forest, std::size_t i, const TreeType& type) {
  const float sx = forest.scaleXZ[i], sy = forest.scaleY[i];
  const float c = std::cos(forest.yaw[i]), s = std::sin(forest.yaw[i]);
  const glm::vec3 local(type.bounds.x * sx, type.bounds.y * sy, type.bounds.z * sx);
  const glm::vec3 centre =
      forest.position[i] + glm::vec3(c * local.x - s * local.z, local.y, s * local.x + c * local.z);
  return {centre, type.bounds.w * std::max(sx, sy)};
}

std::vector<int> typesOf(const Forest& forest) {
  return typesIn(forest.type, forest.blendType);
}

void buildTypesOf(const Forest& forest, const TreeLibrary& library) {
  library.build(typesOf(forest));
}

std::vector<int> librarySpeciesOf(const TreeSnapshot& snapshot, const TreeLibrary& library,
                                  const std::string& where) {
  return SpeciesNumbering(library, where).of(snapshot.speciesNames);
}

const std::vector<int>& SpeciesNumbering::of(const std::vector<std::string>& names) {
  for (std::size_t s = numbered_.size(); s < names.size(); ++s)
    numbered_.push_back(librarySpeciesNamed(names[s], library_, where_));
  return numbered_;
}

Forest forestFromSnapshot(const TreeSnapshot& snapshot, const TreeLibrary& library,
                          const std::string& where) {
  Forest forest;
  forest.resize(snapshot.trees.size());
  placeRows(forest, 0, snapshot.trees, librarySpeciesOf(snapshot, library, where), library);
  return forest;
}

Forest forestFromRun(const RunFolder& run, int year, const TreeLibrary& library,
                     const TreeFilter& keep) {
  Forest forest;
  if (!keep) forest.reserve(snapshotRowsAtMost(run, year));  // no array grows past its rows
  SpeciesNumbering librarySpecies(library, run.dir.string());
  readSnapshotInBatches(
      run, year, keep,
      [&](std::span<const TreeRow> rows, const std::vector<std::string>& speciesNames) {
        const std::size_t start = forest.size();
        forest.resize(start + rows.size());
        placeRows(forest, start, rows, librarySpecies.of(speciesNames), library);
      });
  return forest;
}

void forEachForestBatch(const RunFolder& run, int year, const TreeLibrary& library,
                        const std::function<void(const Forest&)>& each) {
  SpeciesNumbering librarySpecies(library, run.dir.string());
  Forest batch;
  readSnapshotInBatches(
      run, year, {},
      [&](std::span<const TreeRow> rows, const std::vector<std::string>& speciesNames) {
        batch.resize(rows.size());
        placeRows(batch, 0, rows, librarySpecies.of(speciesNames), library);
        each(batch);
      });
}

SiteShaping siteShapingOf(const TreeRow& tree, const TreeLibrary& library) {
  SiteShaping site;
  if (!library.settings().shaping) return site;
  site.light = {tree.site.light.x, -tree.site.light.y};
  site.wind = {tree.site.wind.x, -tree.site.wind.y};
  site.clearBole = tree.height_m > 0.0f ? tree.crownBase_m / tree.height_m : 0.0;
  return site;
}

glm::vec2 drawnLean(const TreeLibrary& library, int type, const SiteShaping& site) {
  return drawnLean(library, type, glm::vec2(shapingLean(site)));
}

glm::vec2 drawnLean(const TreeLibrary& library, int type, glm::vec2 siteLean) {
  return library.type(type).leanResponse.basesFor(siteLean);
}

Forest demoForest(const Terrain& terrain, const TreeLibrary& library, std::size_t count,
                  std::uint64_t seed) {
  Forest forest;
  forest.reserve(count);
  const Grid& g = terrain.grid;
  const int speciesCount = static_cast<int>(library.species().size());
  if (speciesCount == 0) return forest;
  for (std::size_t i = 0; i < count; ++i) {
    Rng rng(streamKey(seed, i, purpose("render.demo")));
    const double east = rng.uniform(0.0, g.eastOf(g.width - 1));
    const double north = rng.uniform(0.0, g.northOf(0));
    const int species = static_cast<int>(rng.uniform() * speciesCount);
    const float maxHeight = library.maxHeight_m(species);
    // Mostly grown trees with some regeneration: the square root leans toward tall.
    const float height = maxHeight * static_cast<float>(0.05 + 0.95 * std::sqrt(rng.uniform()));
    const std::uint64_t individual = rng.nextBits();
    const int type = library.typeFor(species, individual, height, maxHeight);
    forest.add(library, type, worldFromMap(east, north, terrain.altitudeAt(east, north)), height,
               0.0f, static_cast<float>(rng.uniform(0.5, 1.0)), individual);
  }
  buildTypesOf(forest, library);
  return forest;
}

}  // namespace eco
