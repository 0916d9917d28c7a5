#include "app/data_paths.hpp"

#include <cstdlib>

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace eco {

TEST(DataPaths, BareNamesResolveInTheSpeciesFolder) {
  unsetenv("ECOFOREST_DATA_DIR");
  EXPECT_EQ(resolveSpecies("beech"),
            std::filesystem::path(ECOFOREST_DATA_DIR) / "species" / "beech.toml");
  EXPECT_EQ(resolveSpecies("my/oak.toml"), std::filesystem::path("my/oak.toml"));  // paths as given
  EXPECT_EQ(resolveSpecies("oak.toml"), std::filesystem::path("oak.toml"));
}

TEST(DataPaths, UnknownNameListsTheKnownOnes) {
  unsetenv("ECOFOREST_DATA_DIR");
  try {
    resolveSpecies("baobab");
    FAIL() << "no error";
  } catch (const InputError& error) {
    std::string text = error.what();
    EXPECT_NE(text.find("baobab: unknown species"), std::string::npos) << text;
    EXPECT_NE(text.find("beech, birch, maple, pine, shrub"), std::string::npos) << text;
  }
}

TEST(DataPaths, LSystemNamesFindTheShippedGrammars) {
  unsetenv("ECOFOREST_DATA_DIR");
  EXPECT_EQ(resolveLSystem("abop_1_24a"), dataDirectory() / "lsystems" / "abop_1_24a.lsys");
  EXPECT_EQ(resolveLSystem("mine.lsys"), std::filesystem::path("mine.lsys"));
  EXPECT_THROW(resolveLSystem("no_such_grammar"), InputError);
}

TEST(DataPaths, EnvironmentOverridesTheDataFolder) {
  setenv("ECOFOREST_DATA_DIR", "/elsewhere", 1);
  EXPECT_EQ(dataDirectory(), std::filesystem::path("/elsewhere"));
  unsetenv("ECOFOREST_DATA_DIR");
}

}  // namespace eco
