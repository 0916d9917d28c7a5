// Shared helpers of the command-line tests that need a run folder.
#pragma once

#include <filesystem>
#include <string>

#include "test_files.hpp"

namespace eco::test {

// Runs the ecoforest program with these arguments.
CommandResult ecoforest(const std::string& arguments);
// A 20-year run of the default scenario (snapshots of years 10 and 20), made once per test
// process.
const std::filesystem::path& shortDefaultRun();

}  // namespace eco::test
