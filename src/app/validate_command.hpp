// `ecoforest validate`: runs a scenario with a [validation] table and compares its planted
// stand with the published yield table (docs/validation.md).
#pragma once

#include <CLI/CLI.hpp>

namespace eco {

void addValidateCommand(CLI::App& app);

}  // namespace eco
