// The forest at any moment between two snapshots of a run, for growth time-lapses in which
// nothing pops (docs/rendering.md): trees alive in both grow continuously in height, crown
// and vigor and blend between age classes; a tree that established in between appears in its
// year of establishment (its age in the later snapshot says when) and grows from a seedling;
// a tree that died in between fades out over the interval.
#pragma once

#include <string>

#include "render/scene/forest.hpp"
#include "render/scene/tree_library.hpp"
#include "sim/run/run_folder.hpp"

namespace eco {

// `year` lies between before.year and after.year (inclusive); `where` names the run for
// errors about species.
Forest forestBetween(const TreeSnapshot& before, const TreeSnapshot& after, double year,
                     const TreeLibrary& library, const std::string& where);

}  // namespace eco
