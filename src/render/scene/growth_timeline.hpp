// The forest at any moment between two snapshots of a run, for growth time-lapses in which
// nothing pops (docs/rendering.md): trees alive in both grow continuously in height, crown
// and vigor and blend between age classes; a tree that established in between appears in its
// year of establishment (its age in the later snapshot says when) and grows from a seedling;
// a tree that died in between fades out over the interval.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/scene/forest.hpp"
#include "render/scene/tree_library.hpp"
#include "sim/run/run_folder.hpp"

namespace eco {

// Two snapshots and how their trees pair up (by id), matched once: each frame of the
// interval is then made from the pairs, its trees side by side. The snapshots and the
// library are the caller's and must outlive it; `where` names the run for errors about
// species.
class GrowthInterval {
 public:
  GrowthInterval(const TreeSnapshot& before, const TreeSnapshot& after, const TreeLibrary& library,
                 const std::string& where);

  // The forest at `year`, between before.year and after.year (inclusive): the trees of the
  // earlier snapshot in its order (those that die fading out), then the newcomers in the
  // later one's order from their year of establishment.
  Forest forestAt(double year) const;

 private:
  const TreeSnapshot& before_;
  const TreeSnapshot& after_;
  const TreeLibrary& library_;
  std::vector<int> speciesBefore_, speciesAfter_;  // the library's species of each's names
  std::vector<std::int64_t> laterOf_;     // each earlier tree's row in the later one, or -1
  std::vector<std::uint32_t> newcomers_;  // the later snapshot's rows not in the earlier
};

}  // namespace eco
