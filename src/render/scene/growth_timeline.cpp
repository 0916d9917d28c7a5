#include "render/scene/growth_timeline.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_map>

#include <tbb/parallel_for.h>
#include <glm/common.hpp>

#include "core/error.hpp"
#include "render/scene/camera.hpp"

namespace eco {

GrowthInterval::GrowthInterval(const TreeSnapshot& before, const TreeSnapshot& after,
                               const TreeLibrary& library, const std::string& where)
    : before_(before),
      after_(after),
      library_(library),
      speciesBefore_(librarySpeciesOf(before, library, where)),
      speciesAfter_(librarySpeciesOf(after, library, where)) {
  ECO_ASSERT(after.trees.size() <= std::numeric_limits<std::uint32_t>::max(),
             "more trees than 32-bit rows index");
  std::unordered_map<std::uint64_t, std::size_t> afterById;
  afterById.reserve(after.trees.size());
  for (std::size_t i = 0; i < after.trees.size(); ++i) afterById.emplace(after.trees[i].id, i);
  std::vector<char> matched(after.trees.size(), 0);
  laterOf_.resize(before.trees.size());
  for (std::size_t i = 0; i < before.trees.size(); ++i) {
    const auto found = afterById.find(before.trees[i].id);
    laterOf_[i] = found == afterById.end() ? -1 : static_cast<std::int64_t>(found->second);
    if (found != afterById.end()) matched[found->second] = 1;
  }
  for (std::size_t i = 0; i < after.trees.size(); ++i)
    if (!matched[i]) newcomers_.push_back(static_cast<std::uint32_t>(i));
}

Forest GrowthInterval::forestAt(double year) const {
  const double span = std::max(after_.year - before_.year, 1);
  const float f = static_cast<float>(std::clamp((year - before_.year) / span, 0.0, 1.0));
  // A newcomer established in the year its age counts from (not before the earlier snapshot).
  auto established = [&](const TreeRow& tree) {
    return std::max<double>(after_.year - tree.age_years, before_.year);
  };
  // The places of the trees shown: every earlier tree but those dead by the end, and the
  // newcomers established by `year`, each in its order.
  const std::size_t earlier = before_.trees.size();
  std::vector<std::size_t> place(earlier + newcomers_.size() + 1, 0);
  tbb::parallel_for(std::size_t{0}, earlier + newcomers_.size(), [&](std::size_t k) {
    place[k + 1] = k < earlier ? (laterOf_[k] >= 0 || f < 1.0f)
                               : year >= established(after_.trees[newcomers_[k - earlier]]);
  });
  std::partial_sum(place.begin(), place.end(), place.begin());

  Forest forest;
  forest.resize(place.back());
  // The site's shaping, as the later snapshot has it where there is one (a tree's site
  // changes little in a few years; its form follows the later).
  std::vector<SiteShaping> sites(forest.size());
  auto put = [&](std::size_t slot, const TreeRow& tree, const TreeRow& shapedAs, int species,
                 float height, float crown, float vigor, float presence) {
    const SiteShaping& site = sites[slot] = siteShapingOf(shapedAs, library_);
    const TreeLibrary::Blend blend = library_.blendFor(
        species, tree.variantSeed, height, library_.maxHeight_m(species), site.clearBole);
    forest.place(slot, library_, blend.type, worldFromMap(tree.east_m, tree.north_m, tree.ground_m),
                 height, crown, vigor, tree.variantSeed ^ tree.id);
    forest.blendType[slot] = blend.blendType;
    forest.blendWeight[slot] = blend.blendWeight;
    forest.presence[slot] = presence;
  };
  tbb::parallel_for(std::size_t{0}, earlier + newcomers_.size(), [&](std::size_t k) {
    if (place[k + 1] == place[k]) return;  // not shown
    const std::size_t slot = place[k];
    if (k < earlier) {
      const TreeRow& tree = before_.trees[k];
      const int species = speciesBefore_[tree.species];
      if (laterOf_[k] < 0) {  // died in between: fades out over the interval
        put(slot, tree, tree, species, tree.height_m, tree.crownRadius_m, tree.vigor, 1.0f - f);
        return;
      }
      const TreeRow& later = after_.trees[static_cast<std::size_t>(laterOf_[k])];
      put(slot, tree, later, species, glm::mix(tree.height_m, later.height_m, f),
          glm::mix(tree.crownRadius_m, later.crownRadius_m, f),
          glm::mix(tree.vigor, later.vigor, f), 1.0f);
      return;
    }
    // Established in between; it appears over its first year and grows from a seedling to
    // its height in the later snapshot.
    const TreeRow& tree = after_.trees[newcomers_[k - earlier]];
    const int species = speciesAfter_[tree.species];
    const double from = established(tree);
    const double growing = after_.year - from;
    const float g = growing > 0.0 ? static_cast<float>((year - from) / growing) : 1.0f;
    const float seedling = std::min(library_.seedlingHeight_m(species), tree.height_m);
    put(slot, tree, tree, species, glm::mix(seedling, tree.height_m, g),
        glm::mix(0.0f, tree.crownRadius_m, g), tree.vigor,
        static_cast<float>(std::clamp(year - from, 0.0, 1.0)));
  });
  // The leans read the built types' responses.
  buildTypesOf(forest, library_);
  tbb::parallel_for(std::size_t{0}, forest.size(), [&](std::size_t i) {
    forest.lean[i] = drawnLean(library_, forest.type[i], sites[i]);
  });
  return forest;
}

Forest forestBetween(const TreeSnapshot& before, const TreeSnapshot& after, double year,
                     const TreeLibrary& library, const std::string& where) {
  return GrowthInterval(before, after, library, where).forestAt(year);
}

}  // namespace eco
