#include "render/scene/tree_library.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "render/scene/crown_shade.hpp"

namespace eco {
namespace {

glm::vec4 boundingSphere(const WindLods& meshes) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const WindMesh& lod : meshes.lods)
    for (const WindPart& part : lod.parts)
      for (const TreeVertex& v : part.vertices) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
      }
  const glm::vec3 centre(0.0f, 0.5f * (lo.y + hi.y), 0.0f);  // on the stem axis
  float radius = 0.0f;
  for (const WindMesh& lod : meshes.lods)
    for (const WindPart& part : lod.parts)
      for (const TreeVertex& v : part.vertices)
        radius = std::max(radius, glm::length(v.position - centre));
  return {centre, radius};
}

// Each triangle of LOD0 widens every slice its height spans to its farthest vertex (a
// triangle is no wider than its corners), so the envelope holds the whole surface.
std::array<float, TreeType::kEnvelopeBins> envelopeOf(const WindMesh& lod0, float height_m) {
  std::array<float, TreeType::kEnvelopeBins> envelope{};
  const float binsPerMetre = TreeType::kEnvelopeBins / height_m;
  auto bin = [&](float y) {
    return std::clamp(static_cast<int>(std::floor(y * binsPerMetre)), 0,
                      TreeType::kEnvelopeBins - 1);
  };
  for (const WindPart& part : lod0.parts)
    for (std::size_t t = 0; t + 2 < part.indices.size(); t += 3) {
      float low = std::numeric_limits<float>::max(), high = -low, reach = 0.0f;
      for (std::size_t k = 0; k < 3; ++k) {
        const glm::vec3 p = part.vertices[part.indices[t + k]].position;
        low = std::min(low, p.y), high = std::max(high, p.y);
        reach = std::max(reach, std::hypot(p.x, p.z));
      }
      for (int b = bin(low); b <= bin(high); ++b) envelope[b] = std::max(envelope[b], reach);
    }
  return envelope;
}

void measureSizes(TreeType& type, const SkeletonMeasures& rest) {
  // An L-system may draw nothing in its first steps: such a type is empty, not a /0.
  type.height_m = std::max(static_cast<float>(rest.height_m), 1e-3f);
  type.crownRadius_m = static_cast<float>(rest.crownRadius_m);
}

void measureMeshes(TreeType& type) {
  type.bounds = boundingSphere(type.meshes);
  type.envelope_m = envelopeOf(type.meshes.lods[0], type.height_m);
}

}  // namespace

LibrarySpecies loadLibrarySpecies(const std::filesystem::path& file) {
  return {loadSpecies(file), readEcology(file)};
}

std::vector<LibrarySpecies> loadLibrarySpecies(const Scenario& scenario) {
  std::vector<LibrarySpecies> species;
  for (const ScenarioSpecies& s : scenario.species) species.push_back(loadLibrarySpecies(s.file));
  return species;
}

TreeLibrary::TreeLibrary(std::vector<LibrarySpecies> species, const LibrarySettings& settings)
    : settings_(settings) {
  for (LibrarySpecies& s : species) species_.push_back(std::move(s.model));
  ECO_ASSERT(
      settings.variants >= 1 && !settings.ageClasses.empty() && !settings.clearBoleClasses.empty(),
      "variants=" << settings.variants);
  for (int s = 0; s < static_cast<int>(species_.size()); ++s)
    for (int v = 0; v < settings.variants; ++v)
      for (int a = 0; a < static_cast<int>(settings.ageClasses.size()); ++a)
        for (int c = 0; c < static_cast<int>(settings.clearBoleClasses.size()); ++c) {
          TreeType& type = types_.emplace_back();
          type.species = s;
          type.variant = v;
          type.ageClass = a;
          type.crownClass = c;
          type.seed = variantSeed(v);
          type.age = settings.ageClasses[a];
          type.clearBole = settings.clearBoleClasses[c];
        }
  // Every type's sizes now (typeFor() compares them), its meshes on first use.
  tbb::parallel_for(std::size_t{0}, types_.size(), [&](std::size_t i) {
    TreeType& type = types_[i];
    measureSizes(
        type, measure(restSkeleton(species_[type.species], type.seed, type.age, type.clearBole)));
    type.impostorSource = typeIndex(type.species, 0, type.ageClass, type.crownClass);
  });
  built_ = std::make_unique<std::once_flag[]>(types_.size());
  const int classes = static_cast<int>(settings.ageClasses.size());
  for (int s = 0; s < static_cast<int>(species.size()); ++s) {
    const std::optional<Ecology>& ecology = species[s].ecology;
    maxHeight_m_.push_back(ecology ? static_cast<float>(ecology->life.height_m.max())
                                   : types_[typeIndex(s, 0, classes - 1)].height_m);
    seedlingHeight_m_.push_back(
        static_cast<float>((ecology ? ecology->life : LifeHistory{}).seedlingHeight_m));
  }
}

void measureType(TreeType& type, const SkeletonMeasures& rest) {
  measureSizes(type, rest);
  measureMeshes(type);
}

const TreeType& TreeLibrary::type(int index) const {
  ECO_ASSERT(index >= 0 && index < typeCount(), "type " << index);
  TreeType& type = types_[index];
  if (grid_)
    // The build runs TBB loops (an L-system's derivation): isolated, so that this thread
    // does not take up another task of a loop around it meanwhile, which might ask for this
    // very type and wait on itself.
    std::call_once(built_[index], [&] { tbb::this_task_arena::isolate([&] { buildType(type); }); });
  return type;
}

void TreeLibrary::build(std::span<const int> types) const {
  tbb::parallel_for(std::size_t{0}, types.size(), [&](std::size_t i) { type(types[i]); });
}

void TreeLibrary::buildType(TreeType& type) const {
  const Species& s = species_[type.species];
  TreeSkeleton rest;
  type.meshes = buildWindLods(s, type.seed, type.age, &rest, type.clearBole);
  if (settings_.shaping)
    type.leanResponse =
        measureLeanResponse(s, type.seed, type.age, type.clearBole, type.meshes.lods[0]);
  const CrownShade shade(rest, s);  // LOD0's leaves shade every level alike
  for (WindMesh& lod : type.meshes.lods) shadeVertices(lod, shade);
  measureMeshes(type);
  ++builtCount_;
}

TreeLibrary::TreeLibrary(std::vector<Species> species, std::vector<TreeType> types)
    : species_(std::move(species)), grid_(false) {
  for (std::size_t t = 0; t < types.size(); ++t) setType(static_cast<int>(t), std::move(types[t]));
  for (std::size_t s = 0; s < species_.size(); ++s) {
    float tallest = 1e-3f;
    for (const TreeType& type : types_)
      if (type.species == static_cast<int>(s)) tallest = std::max(tallest, type.height_m);
    maxHeight_m_.push_back(tallest);
    seedlingHeight_m_.push_back(static_cast<float>(LifeHistory{}.seedlingHeight_m));
  }
}

void TreeLibrary::setType(int index, TreeType type) {
  ECO_ASSERT(!grid_ && index >= 0 && index <= static_cast<int>(types_.size()) &&
                 type.species >= 0 && type.species < static_cast<int>(species_.size()),
             "type " << index << " of species " << type.species);
  type.impostorSource = index;
  if (index == static_cast<int>(types_.size()))
    types_.push_back(std::move(type));
  else
    types_[index] = std::move(type);
}

int TreeLibrary::typeIndex(int species, int variant, int ageClass, int crownClass) const {
  ECO_ASSERT(grid_, "typeIndex of a library of given types");
  const int ages = static_cast<int>(settings_.ageClasses.size());
  const int crowns = static_cast<int>(settings_.clearBoleClasses.size());
  return ((species * settings_.variants + variant) * ages + ageClass) * crowns + crownClass;
}

int TreeLibrary::crownClassFor(double clearBole) const {
  const std::vector<double>& classes = settings_.clearBoleClasses;
  int nearest = 0;
  for (int c = 1; c < static_cast<int>(classes.size()); ++c)
    if (std::abs(classes[c] - clearBole) < std::abs(classes[nearest] - clearBole)) nearest = c;
  return nearest;
}

TreeLibrary::Blend TreeLibrary::blendFor(int species, std::uint64_t variantSeed, float height_m,
                                         float speciesMaxHeight_m, double clearBole) const {
  const int variant =
      static_cast<int>(variantSeed % static_cast<std::uint64_t>(settings_.variants));
  const int classes = static_cast<int>(settings_.ageClasses.size());
  const int crown = crownClassFor(clearBole);
  auto type = [&](int a) { return typeIndex(species, variant, a, crown); };
  // Pruning keeps the height, so every crown class has the open-grown class heights.
  const float mature = types_[type(classes - 1)].height_m;
  const float relative = std::max(height_m, 1e-3f) / std::max(speciesMaxHeight_m, 1e-3f);
  auto classRelative = [&](int a) { return types_[type(a)].height_m / mature; };
  if (relative <= classRelative(0)) return {type(0)};
  for (int a = 0; a + 1 < classes; ++a)
    if (relative < classRelative(a + 1))
      return {type(a), type(a + 1),
              std::log(relative / classRelative(a)) /
                  std::log(classRelative(a + 1) / classRelative(a))};
  return {type(classes - 1)};
}

int TreeLibrary::typeFor(int species, std::uint64_t variantSeed, float height_m,
                         float speciesMaxHeight_m, double clearBole) const {
  // The nearer of the two classes around the plant (class heights grow with age), in
  // logarithms: the blend's weight rounded.
  const Blend blend = blendFor(species, variantSeed, height_m, speciesMaxHeight_m, clearBole);
  return blend.blendType >= 0 && blend.blendWeight > 0.5f ? blend.blendType : blend.type;
}

}  // namespace eco
