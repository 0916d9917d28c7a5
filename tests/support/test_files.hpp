// File helpers shared by the test suites of every module.
#pragma once

#include <filesystem>
#include <string>

namespace eco::test {

// An empty folder under the temporary directory, unique to this process, removed when the
// process ends unless a test failed (or ECOFOREST_KEEP_TEST_FILES is set).
std::filesystem::path freshDirectory(const std::string& name);
std::string readFile(const std::filesystem::path& file);
void writeFile(const std::filesystem::path& file, const std::string& text);
std::size_t entriesIn(const std::filesystem::path& folder);

struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};
// Runs a shell command and collects what it prints.
CommandResult runCommand(const std::string& command);

}  // namespace eco::test
