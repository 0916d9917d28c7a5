// The forest at any moment between two snapshots of a run, for growth time-lapses in which
// nothing pops (docs/rendering.md): trees alive in both grow continuously in height, crown
// and vigor and blend between age classes; a tree that established in between appears in its
// year of establishment (its age in the later snapshot says when) and grows from a seedling;
// a tree that died in between fades out over the interval.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/scene/forest.hpp"
#include "render/scene/tree_library.hpp"
#include "sim/run/run_folder.hpp"

namespace eco {

// A snapshot's rows as GrowthInterval reads them: in memory already (which must outlive the
// reading), or read from a run's file a batch of rows at a time, never whole.
struct SnapshotRows {
  int year = 0;
  std::size_t rowsAtMost = 0;                  // room for them
  std::function<void(const TreeBatch&)> read;  // hands each batch on, in the file's order
  static SnapshotRows of(const TreeSnapshot& snapshot);
  static SnapshotRows of(const RunFolder& run, int year);  // year 0: the bare landscape
};

// Two snapshots' trees paired by id once, each frame of the interval then made from the
// pairs side by side. Only what a frame draws is kept of each tree (about 63 bytes), once
// whether it lives in both snapshots or one: a landscape's interval of 105 and 66 million
// plants would hold 15 GB as the snapshots' rows. The library is the caller's and must
// outlive it.
class GrowthInterval {
 public:
  // `where` names the snapshots in errors about species or ids.
  GrowthInterval(const SnapshotRows& before, const SnapshotRows& after, const TreeLibrary& library,
                 const std::string& where);
  GrowthInterval(const TreeSnapshot& before, const TreeSnapshot& after, const TreeLibrary& library,
                 const std::string& where)
      : GrowthInterval(SnapshotRows::of(before), SnapshotRows::of(after), library, where) {}

  // The forest at `year`, between the two snapshots' years (inclusive): the trees of the
  // earlier snapshot in its order (those that die fading out), then the newcomers in the
  // later one's order from their year of establishment.
  Forest forestAt(double year) const;
  // The part of it made from trees first .. last - 1 of those it keeps (size()): the forests
  // of consecutive ranges, one after another, are forestAt(year) tree for tree, so a frame
  // can be made a part at a time.
  Forest forestAt(double year, std::size_t first, std::size_t last) const;
  // The trees it keeps: every earlier one and each newcomer.
  std::size_t size() const { return position_.size(); }
  // The most memory an interval between snapshots of these many rows takes, while its trees
  // are paired: each tree's columns, and each earlier tree's id sorted for the search.
  static std::uint64_t peakBytes(std::size_t rowsBefore, std::size_t rowsAfter);

 private:
  // Tree k as `tree` has it, both its states alike; then its later state and site.
  void keep(std::size_t k, const TreeRow& tree, int species);
  void keepLater(std::size_t k, const TreeRow& later);

  int fromYear_ = 0, toYear_ = 0;
  const TreeLibrary& library_;
  std::size_t earlier_ = 0;  // the earlier snapshot's trees come first, then the newcomers
  // Each tree as the earlier snapshot has it (a newcomer as the later one does).
  std::vector<glm::vec3> position_;
  std::vector<std::uint64_t> individual_;  // its variant seed ^ id: the instance's draws
  std::vector<std::uint32_t> variantSeed_;
  std::vector<std::int16_t> species_;  // the library's
  // (earlier, later) of the trees in both; a newcomer's later in y, a dying tree's in x.
  std::vector<glm::vec2> height_, crownRadius_, vigor_;
  // The site's lean (shapingLean) and clear bole, as the later snapshot has them where there
  // is one: a tree's site changes little in a few years, and its form follows the later.
  std::vector<glm::vec2> siteLean_;
  std::vector<float> clearBole_;
  std::vector<std::uint8_t> lives_;  // each earlier tree: is it in the later snapshot?
  std::vector<float> established_;   // each newcomer: the year it appears
};

}  // namespace eco
