#include "app/data_paths.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "core/error.hpp"

namespace eco {

std::filesystem::path dataDirectory() {
  if (const char* fromEnvironment = std::getenv("ECOFOREST_DATA_DIR");
      fromEnvironment && *fromEnvironment)
    return fromEnvironment;
  return ECOFOREST_DATA_DIR;
}

namespace {

std::filesystem::path resolveNamed(const std::string& nameOrPath,
                                   const std::filesystem::path& folder, const char* what,
                                   const std::string& extension = ".toml") {
  std::filesystem::path given(nameOrPath);
  if (nameOrPath.find('/') != std::string::npos || given.extension() == extension) return given;
  std::filesystem::path file = folder / (nameOrPath + extension);
  if (std::filesystem::exists(file)) return file;
  std::vector<std::string> known;
  std::error_code ignored;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ignored))
    if (entry.path().extension() == extension) known.push_back(entry.path().stem().string());
  std::sort(known.begin(), known.end());
  std::string list;
  for (const std::string& name : known) list += (list.empty() ? "" : ", ") + name;
  throw InputError({nameOrPath, 0, ""}, std::string("unknown ") + what + " (looked in " +
                                            folder.string() +
                                            "; available: " + (list.empty() ? "none" : list) + ")");
}

}  // namespace

std::filesystem::path resolveSpecies(const std::string& nameOrPath) {
  return resolveNamed(nameOrPath, dataDirectory() / "species", "species");
}

std::filesystem::path resolveScenario(const std::string& nameOrPath) {
  return resolveNamed(nameOrPath, dataDirectory(), "scenario");
}

std::filesystem::path resolveLSystem(const std::string& nameOrPath) {
  return resolveNamed(nameOrPath, dataDirectory() / "lsystems", "L-system", ".lsys");
}

}  // namespace eco
