#include "app/data_paths.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "core/error.hpp"
#include "core/names.hpp"
#include "core/toml_reader.hpp"

namespace eco {

std::filesystem::path dataDirectory() {
  if (const char* fromEnvironment = std::getenv("ECOFOREST_DATA_DIR");
      fromEnvironment && *fromEnvironment)
    return fromEnvironment;
  return ECOFOREST_DATA_DIR;
}

namespace {

// A data file's names: its file name's stem and, for species, the common names it lists.
struct NamedFile {
  std::string name;
  std::filesystem::path file;
};

std::vector<std::string> commonNamesIn(const std::filesystem::path& speciesFile) {
  try {
    TomlDocument document = TomlDocument::load(speciesFile);
    return document.root().stringList("common_names", {});
  } catch (const InputError&) {
    return {};  // a broken file is reported when it is used, not while others are looked up
  }
}

// Names are matched ignoring case; a near miss is suggested.
std::filesystem::path resolveNamed(const std::string& nameOrPath,
                                   const std::filesystem::path& folder, const char* what,
                                   const std::string& extension = ".toml",
                                   bool withCommonNames = false) {
  std::filesystem::path given(nameOrPath);
  if (nameOrPath.find('/') != std::string::npos || given.extension() == extension) return given;
  std::filesystem::path file = folder / (nameOrPath + extension);
  if (std::filesystem::exists(file)) return file;
  std::vector<NamedFile> known;
  std::error_code ignored;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ignored)) {
    if (entry.path().extension() != extension) continue;
    known.push_back({entry.path().stem().string(), entry.path()});
    if (withCommonNames)
      for (std::string& name : commonNamesIn(entry.path())) known.push_back({name, entry.path()});
  }
  std::sort(known.begin(), known.end(),
            [](const NamedFile& a, const NamedFile& b) { return a.name < b.name; });
  for (const NamedFile& k : known)
    if (sameNameIgnoringCase(k.name, nameOrPath)) return k.file;
  std::vector<std::string> names;
  std::string list;
  for (const NamedFile& k : known) {
    names.push_back(k.name);
    if (k.file.stem() == k.name) list += (list.empty() ? "" : ", ") + k.name;
  }
  throw InputError({nameOrPath, 0, ""},
                   std::string("unknown ") + what + didYouMean(nameOrPath, names) + " (looked in " +
                       folder.string() + "; available: " + (list.empty() ? "none" : list) + ")");
}

}  // namespace

std::filesystem::path resolveSpecies(const std::string& nameOrPath) {
  return resolveNamed(nameOrPath, dataDirectory() / "species", "species", ".toml", true);
}

std::filesystem::path resolveScenario(const std::string& nameOrPath) {
  return resolveNamed(nameOrPath, dataDirectory(), "scenario");
}

std::filesystem::path resolveLSystem(const std::string& nameOrPath) {
  return resolveNamed(nameOrPath, dataDirectory() / "lsystems", "L-system", ".lsys");
}

}  // namespace eco
