// `ecoforest tree`: build one tree, print its measures, export it.
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addTreeCommand(CLI::App& app);

}  // namespace eco
