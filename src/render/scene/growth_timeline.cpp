#include "render/scene/growth_timeline.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <numeric>
#include <utility>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
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
  // The later trees' ids in order, each with its row, searched for each earlier tree's,
  // side by side (a landscape's hundred million: 16 bytes each, where a hash map takes 40).
  std::vector<std::pair<std::uint64_t, std::uint32_t>> afterById(after.trees.size());
  tbb::parallel_for(std::size_t{0}, after.trees.size(), [&](std::size_t i) {
    afterById[i] = {after.trees[i].id, static_cast<std::uint32_t>(i)};
  });
  tbb::parallel_sort(afterById.begin(), afterById.end());
  std::vector<char> matched(after.trees.size(), 0);
  laterOf_.resize(before.trees.size());
  tbb::parallel_for(std::size_t{0}, before.trees.size(), [&](std::size_t i) {
    const std::uint64_t id = before.trees[i].id;
    const auto found = std::lower_bound(afterById.begin(), afterById.end(),
                                        std::pair<std::uint64_t, std::uint32_t>{id, 0});
    laterOf_[i] = found != afterById.end() && found->first == id
                      ? static_cast<std::int64_t>(found->second)
                      : -1;
    // Atomic: a crafted file may repeat an id, so that two earlier trees find one row.
    if (laterOf_[i] >= 0)
      std::atomic_ref(matched[found->second]).store(1, std::memory_order_relaxed);
  });
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
  // The site's shaping of tree k, as the later snapshot has it where there is one (a tree's
  // site changes little in a few years; its form follows the later).
  auto siteOf = [&](std::size_t k) {
    const TreeRow& shapedAs = k >= earlier ? after_.trees[newcomers_[k - earlier]]
                              : laterOf_[k] < 0
                                  ? before_.trees[k]
                                  : after_.trees[static_cast<std::size_t>(laterOf_[k])];
    return siteShapingOf(shapedAs, library_);
  };
  auto put = [&](std::size_t k, const TreeRow& tree, int species, float height, float crown,
                 float vigor, float presence) {
    const std::size_t slot = place[k];
    const TreeLibrary::Blend blend = library_.blendFor(
        species, tree.variantSeed, height, library_.maxHeight_m(species), siteOf(k).clearBole);
    forest.place(slot, library_, blend.type, worldFromMap(tree.east_m, tree.north_m, tree.ground_m),
                 height, crown, vigor, tree.variantSeed ^ tree.id);
    forest.blendType[slot] = blend.blendType;
    forest.blendWeight[slot] = blend.blendWeight;
    forest.presence[slot] = presence;
  };
  tbb::parallel_for(std::size_t{0}, earlier + newcomers_.size(), [&](std::size_t k) {
    if (place[k + 1] == place[k]) return;  // not shown
    if (k < earlier) {
      const TreeRow& tree = before_.trees[k];
      const int species = speciesBefore_[tree.species];
      if (laterOf_[k] < 0) {  // died in between: fades out over the interval
        put(k, tree, species, tree.height_m, tree.crownRadius_m, tree.vigor, 1.0f - f);
        return;
      }
      const TreeRow& later = after_.trees[static_cast<std::size_t>(laterOf_[k])];
      put(k, tree, species, glm::mix(tree.height_m, later.height_m, f),
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
    put(k, tree, species, glm::mix(seedling, tree.height_m, g),
        glm::mix(0.0f, tree.crownRadius_m, g), tree.vigor,
        static_cast<float>(std::clamp(year - from, 0.0, 1.0)));
  });
  // The leans read the built types' responses.
  buildTypesOf(forest, library_);
  tbb::parallel_for(std::size_t{0}, earlier + newcomers_.size(), [&](std::size_t k) {
    if (place[k + 1] == place[k]) return;
    forest.lean[place[k]] = drawnLean(library_, forest.type[place[k]], siteOf(k));
  });
  return forest;
}

}  // namespace eco
