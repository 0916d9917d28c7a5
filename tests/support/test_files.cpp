#include "test_files.hpp"

#include <unistd.h>
#include <fstream>
#include <iterator>
#include <sstream>

namespace eco::test {

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

std::size_t entriesIn(const std::filesystem::path& folder) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(folder),
                                                std::filesystem::directory_iterator()));
}

}  // namespace eco::test
