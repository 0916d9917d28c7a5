// How `run` and `validate` show a simulation's progress: a bar redrawn in place on a
// terminal, otherwise a plain line about every tenth of the run.
#pragma once

#include "sim/run/simulation.hpp"

namespace eco {

void showRunProgress(const RunProgress& progress, bool terminal);

}  // namespace eco
