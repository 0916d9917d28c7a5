// Shared helpers for the model tests.
#pragma once

#include <filesystem>
#include <string>

#include "model/species.hpp"
#include "test_files.hpp"

namespace eco::test {

// A species from scenarios/species/NAME.toml.
Species loadNamed(const std::string& name);
// The same species with no individual variation, so angles and lengths are the paper's.
Species withoutVariation(Species species);
// Writes `text` to NAME.toml in a fresh folder and returns its path.
std::filesystem::path writeTemporary(const std::string& name, const std::string& text);

}  // namespace eco::test
