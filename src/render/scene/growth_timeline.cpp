#include "render/scene/growth_timeline.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <numeric>
#include <span>
#include <utility>

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <glm/common.hpp>

#include "core/error.hpp"
#include "render/scene/camera.hpp"

namespace eco {

namespace {

// A tree's id and its place in the interval, sorted by id for the pairing's search.
using IdAndPlace = std::pair<std::uint64_t, std::uint32_t>;

template <typename Column>
constexpr std::uint64_t elementBytes() {
  return sizeof(typename Column::value_type);
}

}  // namespace

SnapshotRows SnapshotRows::of(const TreeSnapshot& snapshot) {
  return {snapshot.year, snapshot.trees.size(),
          [&snapshot](const TreeBatch& each) { each(snapshot.trees, snapshot.speciesNames); }};
}

SnapshotRows SnapshotRows::of(const RunFolder& run, int year) {
  if (year == 0) return {0, 0, [](const TreeBatch&) {}};
  return {year, snapshotRowsAtMost(run, year),
          [&run, year](const TreeBatch& each) { readSnapshotInBatches(run, year, {}, each); }};
}

void GrowthInterval::keep(std::size_t k, const TreeRow& tree, int species) {
  position_[k] = worldFromMap(tree.east_m, tree.north_m, tree.ground_m);
  individual_[k] = tree.variantSeed ^ tree.id;
  variantSeed_[k] = tree.variantSeed;
  species_[k] = static_cast<std::int16_t>(species);
  height_[k] = glm::vec2(tree.height_m);
  crownRadius_[k] = glm::vec2(tree.crownRadius_m);
  vigor_[k] = glm::vec2(tree.vigor);
  keepLater(k, tree);
}

void GrowthInterval::keepLater(std::size_t k, const TreeRow& later) {
  height_[k].y = later.height_m;
  crownRadius_[k].y = later.crownRadius_m;
  vigor_[k].y = later.vigor;
  const SiteShaping site = siteShapingOf(later, library_);
  siteLean_[k] = glm::vec2(shapingLean(site));
  clearBole_[k] = static_cast<float>(site.clearBole);  // a float's quotient: exact
}

GrowthInterval::GrowthInterval(const SnapshotRows& before, const SnapshotRows& after,
                               const TreeLibrary& library, const std::string& where)
    : fromYear_(before.year), toYear_(after.year), library_(library) {
  // Every tree's column alike (lives_ and established_ are the earlier trees' and the
  // newcomers' alone).
  auto eachColumn = [&](const auto& apply) {
    apply(position_);
    apply(individual_);
    apply(variantSeed_);
    apply(species_);
    apply(height_);
    apply(crownRadius_);
    apply(vigor_);
    apply(siteLean_);
    apply(clearBole_);
  };
  auto resize = [&](std::size_t n) { eachColumn([&](auto& column) { column.resize(n); }); };
  // Room for every tree of both at most: room a newcomer does not take is never touched.
  const std::size_t room = before.rowsAtMost + after.rowsAtMost;
  eachColumn([&](auto& column) { column.reserve(room); });

  // The earlier trees with their ids, which are sorted to be searched for the later trees'
  // (16 bytes a tree while the later snapshot is read, where a hash map takes 40).
  std::vector<IdAndPlace> earlierById;
  earlierById.reserve(before.rowsAtMost);
  SpeciesNumbering earlierSpecies(library, where);
  before.read([&](std::span<const TreeRow> rows, const std::vector<std::string>& names) {
    const std::vector<int>& species = earlierSpecies.of(names);
    const std::size_t start = size();
    ECO_ASSERT(start + rows.size() <= std::numeric_limits<std::uint32_t>::max(),
               "more trees than 32-bit places index");
    resize(start + rows.size());
    earlierById.resize(start + rows.size());
    tbb::parallel_for(std::size_t{0}, rows.size(), [&](std::size_t i) {
      keep(start + i, rows[i], species[rows[i].species]);
      earlierById[start + i] = {rows[i].id, static_cast<std::uint32_t>(start + i)};
    });
  });
  earlier_ = size();
  tbb::parallel_sort(earlierById.begin(), earlierById.end());
  lives_.assign(earlier_, 0);

  // Each later tree is an earlier one's later state or a newcomer, kept in its order.
  SpeciesNumbering laterSpecies(library, where);
  constexpr std::uint32_t kNewcomer = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> earlierOf, newcomerPlace;
  std::atomic<std::uint64_t> repeatedId{0};  // the least id two later trees share with one
  after.read([&](std::span<const TreeRow> rows, const std::vector<std::string>& names) {
    const std::vector<int>& species = laterSpecies.of(names);
    earlierOf.resize(rows.size());
    newcomerPlace.assign(rows.size() + 1, 0);
    tbb::parallel_for(std::size_t{0}, rows.size(), [&](std::size_t i) {
      const std::uint64_t id = rows[i].id;
      const auto found =
          std::lower_bound(earlierById.begin(), earlierById.end(), IdAndPlace{id, 0});
      earlierOf[i] = found != earlierById.end() && found->first == id ? found->second : kNewcomer;
      newcomerPlace[i + 1] = earlierOf[i] == kNewcomer;
    });
    std::partial_sum(newcomerPlace.begin(), newcomerPlace.end(), newcomerPlace.begin());
    const std::size_t start = size();
    ECO_ASSERT(start + newcomerPlace.back() <= std::numeric_limits<std::uint32_t>::max(),
               "more trees than 32-bit places index");
    resize(start + newcomerPlace.back());
    established_.resize(size() - earlier_);
    tbb::parallel_for(std::size_t{0}, rows.size(), [&](std::size_t i) {
      const TreeRow& tree = rows[i];
      if (earlierOf[i] == kNewcomer) {
        const std::size_t k = start + newcomerPlace[i];
        keep(k, tree, species[tree.species]);
        // Established in the year its age counts from (not before the earlier snapshot).
        established_[k - earlier_] =
            static_cast<float>(std::max(toYear_ - tree.age_years, fromYear_));
        return;
      }
      // A crafted file may repeat an id: two later trees would be one earlier tree's.
      if (std::atomic_ref(lives_[earlierOf[i]]).exchange(1, std::memory_order_relaxed) != 0) {
        std::uint64_t least = repeatedId.load(std::memory_order_relaxed);
        while ((least == 0 || tree.id < least) &&
               !repeatedId.compare_exchange_weak(least, tree.id, std::memory_order_relaxed)) {
        }
        return;
      }
      keepLater(earlierOf[i], tree);
    });
  });
  if (const std::uint64_t id = repeatedId.load(); id != 0)
    throw InputError({where, 0, ""},
                     fmt::format("the snapshot of year {} holds tree id {} twice", toYear_, id));
}

std::uint64_t GrowthInterval::peakBytes(std::size_t rowsBefore, std::size_t rowsAfter) {
  const std::uint64_t perTree =
      elementBytes<decltype(position_)>() + elementBytes<decltype(individual_)>() +
      elementBytes<decltype(variantSeed_)>() + elementBytes<decltype(species_)>() +
      elementBytes<decltype(height_)>() + elementBytes<decltype(crownRadius_)>() +
      elementBytes<decltype(vigor_)>() + elementBytes<decltype(siteLean_)>() +
      elementBytes<decltype(clearBole_)>();
  // An earlier tree's id and place while the later trees are paired, and whether it lives on.
  const std::uint64_t perEarlier = sizeof(IdAndPlace) + elementBytes<decltype(lives_)>();
  const std::uint64_t perNewcomer = elementBytes<decltype(established_)>();
  return (rowsBefore + rowsAfter) * perTree + rowsBefore * perEarlier + rowsAfter * perNewcomer;
}

Forest GrowthInterval::forestAt(double year) const {
  return forestAt(year, 0, size());
}

Forest GrowthInterval::forestAt(double year, std::size_t first, std::size_t last) const {
  const double span = std::max(toYear_ - fromYear_, 1);
  const float f = static_cast<float>(std::clamp((year - fromYear_) / span, 0.0, 1.0));
  // The places of the trees shown: every earlier tree but those dead by the end, and the
  // newcomers established by `year`, each in its order; place[k - first] for tree k.
  const std::size_t n = last - first;
  std::vector<std::uint32_t> place(n + 1, 0);
  tbb::parallel_for(first, last, [&](std::size_t k) {
    place[k - first + 1] =
        k < earlier_ ? (lives_[k] != 0 || f < 1.0f) : year >= established_[k - earlier_];
  });
  std::partial_sum(place.begin(), place.end(), place.begin());

  Forest forest;
  forest.resize(place.back());
  auto put = [&](std::size_t k, float height, float crown, float vigor, float presence) {
    const std::size_t slot = place[k - first];
    const TreeLibrary::Blend blend = library_.blendFor(
        species_[k], variantSeed_[k], height, library_.maxHeight_m(species_[k]), clearBole_[k]);
    forest.place(slot, library_, blend.type, position_[k], height, crown, vigor, individual_[k]);
    forest.blendType[slot] = blend.blendType;
    forest.blendWeight[slot] = blend.blendWeight;
    forest.presence[slot] = presence;
  };
  tbb::parallel_for(first, last, [&](std::size_t k) {
    if (place[k - first + 1] == place[k - first]) return;  // not shown
    if (k < earlier_) {
      if (lives_[k] == 0) {  // died in between: fades out over the interval
        put(k, height_[k].x, crownRadius_[k].x, vigor_[k].x, 1.0f - f);
        return;
      }
      put(k, glm::mix(height_[k].x, height_[k].y, f),
          glm::mix(crownRadius_[k].x, crownRadius_[k].y, f), glm::mix(vigor_[k].x, vigor_[k].y, f),
          1.0f);
      return;
    }
    // Established in between; it appears over its first year and grows from a seedling to
    // its height in the later snapshot.
    const double from = established_[k - earlier_];
    const double growing = toYear_ - from;
    const float g = growing > 0.0 ? static_cast<float>((year - from) / growing) : 1.0f;
    const float seedling = std::min(library_.seedlingHeight_m(species_[k]), height_[k].y);
    put(k, glm::mix(seedling, height_[k].y, g), glm::mix(0.0f, crownRadius_[k].y, g), vigor_[k].y,
        static_cast<float>(std::clamp(year - from, 0.0, 1.0)));
  });
  // The leans read the built types' responses.
  buildTypesOf(forest, library_);
  tbb::parallel_for(first, last, [&](std::size_t k) {
    const std::size_t slot = place[k - first];
    if (place[k - first + 1] == slot) return;
    forest.lean[slot] = drawnLean(library_, forest.type[slot], siteLean_[k]);
  });
  return forest;
}

}  // namespace eco
