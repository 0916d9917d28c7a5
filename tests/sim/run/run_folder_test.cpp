#include "sim/run/run_folder.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

TEST(RunFolder, AFolderWithoutRunJsonIsNotARun) {
  const auto dir = test::freshDirectory("run_folder_none");
  EXPECT_THROW(openRunFolder(dir), InputError);
  EXPECT_THROW(openRunFolder(dir / "missing"), InputError);
}

}  // namespace
}  // namespace eco
