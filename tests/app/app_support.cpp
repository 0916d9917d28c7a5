#include "app_support.hpp"

#include <gtest/gtest.h>

namespace eco::test {

CommandResult ecoforest(const std::string& arguments) {
  return runCommand(std::string(ECOFOREST_EXE) + " " + arguments);
}

const std::filesystem::path& shortDefaultRun() {
  static const std::filesystem::path dir = [] {
    auto d = freshDirectory("app_short_run");
    CommandResult r = ecoforest("run --years 20 --out " + d.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return d;
  }();
  return dir;
}

}  // namespace eco::test
