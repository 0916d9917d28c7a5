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

std::filesystem::path freshDirectory(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("ecoforest_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::filesystem::path writeTemporary(const std::string& name, const std::string& text) {
  auto file = freshDirectory(name) / (name + ".toml");
  std::ofstream(file) << text;
  return file;
}

}  // namespace eco::test
