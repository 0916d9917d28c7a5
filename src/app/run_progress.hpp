// How `run` and `validate` show a simulation's progress: a bar redrawn in place on a
// terminal, otherwise a plain line about every tenth of the run; and its warnings.
#pragma once

#include "sim/run/simulation.hpp"

namespace eco {

void showRunProgress(const RunProgress& progress, bool terminal);
// Sets the options' progress (to stderr, as the terminal allows) and warnings (to stderr).
void reportToTheUser(RunOptions& options);

}  // namespace eco
