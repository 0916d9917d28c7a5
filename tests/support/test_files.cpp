#include "test_files.hpp"

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <mutex>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

namespace eco::test {
namespace {

// The folders this test process made, removed when it ends: a suite run leaves nothing in
// the temporary directory. A failed test's folders are kept to look into, and
// ECOFOREST_KEEP_TEST_FILES=1 keeps every test's.
class MadeFolders {
 public:
  void add(const std::filesystem::path& folder) {
    std::lock_guard<std::mutex> lock(mutex_);
    folders_.push_back(folder);
  }
  ~MadeFolders() {
    if (std::getenv("ECOFOREST_KEEP_TEST_FILES") || ::testing::UnitTest::GetInstance()->Failed())
      return;
    std::error_code ignored;
    for (const std::filesystem::path& folder : folders_)
      std::filesystem::remove_all(folder, ignored);
  }

 private:
  std::mutex mutex_;
  std::vector<std::filesystem::path> folders_;
};

MadeFolders& madeFolders() {
  static MadeFolders folders;
  return folders;
}

}  // namespace

std::filesystem::path freshDirectory(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("ecoforest_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  madeFolders().add(dir);
  return dir;
}

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void writeFile(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
}

std::size_t entriesIn(const std::filesystem::path& folder) {
  return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(folder),
                                                std::filesystem::directory_iterator()));
}

CommandResult runCommand(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::array<char, 4096> buffer{};
  while (std::size_t n = fread(buffer.data(), 1, buffer.size(), pipe))
    result.output.append(buffer.data(), n);
  int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace eco::test
