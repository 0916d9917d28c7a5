// Finding ecoforest's data files (species, scenarios) from a bare name.
#pragma once

#include <filesystem>
#include <string>

namespace eco {

// The scenarios folder: $ECOFOREST_DATA_DIR if set, else the source tree's scenarios/.
std::filesystem::path dataDirectory();

// "beech" -> <data>/species/beech.toml; a path (with a '/' or ending in .toml) is used as
// given. Names match ignoring case ("Beech"), and a species also by the common names its
// file lists ("hazel" -> shrub.toml). Unknown names are an InputError with a "did you
// mean" for a near miss, listing the species that exist.
std::filesystem::path resolveSpecies(const std::string& nameOrPath);
// "valley" -> <data>/valley.toml, likewise.
std::filesystem::path resolveScenario(const std::string& nameOrPath);
// "abop_1_24a" -> <data>/lsystems/abop_1_24a.lsys, likewise.
std::filesystem::path resolveLSystem(const std::string& nameOrPath);

}  // namespace eco
