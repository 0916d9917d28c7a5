#include "test_support.hpp"

#include <unistd.h>
#include <fstream>
#include <sstream>

namespace eco::test {

Species loadNamed(const std::string& name) {
  return loadSpecies(std::filesystem::path(ECOFOREST_DATA_DIR) / "species" / (name + ".toml"));
}

Species withoutVariation(Species species) {
  species.variation = Variation{0.0, 0.0, 0.0};
  return species;
}

std::filesystem::path writeTemporary(const std::string& name, const std::string& text) {
  auto file = freshDirectory(name) / (name + ".toml");
  std::ofstream(file) << text;
  return file;
}

}  // namespace eco::test
