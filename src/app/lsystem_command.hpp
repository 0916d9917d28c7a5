// `ecoforest lsystem`: derive an RL-system grammar, print the string or its measures,
// interpret it with the turtle and export the tree.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addLSystemCommand(CLI::App& app);

}  // namespace eco
