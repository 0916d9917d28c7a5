#include "render/scene/growth_timeline.hpp"

#include <algorithm>
#include <unordered_map>

#include <tbb/parallel_for.h>
#include <glm/common.hpp>

#include "render/scene/camera.hpp"

namespace eco {

Forest forestBetween(const TreeSnapshot& before, const TreeSnapshot& after, double year,
                     const TreeLibrary& library, const std::string& where) {
  const std::vector<int> speciesBefore = librarySpeciesOf(before, library, where);
  const std::vector<int> speciesAfter = librarySpeciesOf(after, library, where);
  const double span = std::max(after.year - before.year, 1);
  const float f = static_cast<float>(std::clamp((year - before.year) / span, 0.0, 1.0));

  std::unordered_map<std::uint64_t, std::size_t> afterById;
  afterById.reserve(after.trees.size());
  for (std::size_t i = 0; i < after.trees.size(); ++i) afterById.emplace(after.trees[i].id, i);

  Forest forest;
  forest.reserve(before.trees.size() + after.trees.size());
  // The site's shaping, as the later snapshot has it where there is one (a tree's site
  // changes little in a few years; its form follows the later).
  std::vector<SiteShaping> sites;
  sites.reserve(before.trees.size() + after.trees.size());
  auto add = [&](const TreeRow& tree, const TreeRow& shapedAs, int species, float height,
                 float crown, float vigor, float presence) {
    const SiteShaping& site = sites.emplace_back(siteShapingOf(shapedAs, library));
    const TreeLibrary::Blend blend = library.blendFor(species, tree.variantSeed, height,
                                                      library.maxHeight_m(species), site.clearBole);
    forest.add(library, blend.type, worldFromMap(tree.east_m, tree.north_m, tree.ground_m), height,
               crown, vigor, tree.variantSeed ^ tree.id);
    forest.blendType.back() = blend.blendType;
    forest.blendWeight.back() = blend.blendWeight;
    forest.presence.back() = presence;
  };

  std::vector<char> matched(after.trees.size(), 0);
  for (const TreeRow& tree : before.trees) {
    const int species = speciesBefore[tree.species];
    auto found = afterById.find(tree.id);
    if (found == afterById.end()) {  // died in between: fades out over the interval
      if (f < 1.0f)
        add(tree, tree, species, tree.height_m, tree.crownRadius_m, tree.vigor, 1.0f - f);
      continue;
    }
    matched[found->second] = 1;
    const TreeRow& later = after.trees[found->second];
    add(tree, later, species, glm::mix(tree.height_m, later.height_m, f),
        glm::mix(tree.crownRadius_m, later.crownRadius_m, f), glm::mix(tree.vigor, later.vigor, f),
        1.0f);
  }
  for (std::size_t i = 0; i < after.trees.size(); ++i) {
    if (matched[i]) continue;
    // Established in between, in the year its age counts from; it appears over its first
    // year and grows from a seedling to its height in the later snapshot.
    const TreeRow& tree = after.trees[i];
    const int species = speciesAfter[tree.species];
    const double established = std::max<double>(after.year - tree.age_years, before.year);
    if (year < established) continue;
    const double growing = after.year - established;
    const float g = growing > 0.0 ? static_cast<float>((year - established) / growing) : 1.0f;
    const float seedling = std::min(library.seedlingHeight_m(species), tree.height_m);
    add(tree, tree, species, glm::mix(seedling, tree.height_m, g),
        glm::mix(0.0f, tree.crownRadius_m, g), tree.vigor,
        static_cast<float>(std::clamp(year - established, 0.0, 1.0)));
  }
  // The leans read the built types' responses.
  buildTypesOf(forest, library);
  tbb::parallel_for(std::size_t{0}, forest.size(), [&](std::size_t i) {
    forest.lean[i] = drawnLean(library, forest.type[i], sites[i]);
  });
  return forest;
}

}  // namespace eco
