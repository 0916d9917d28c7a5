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

TEST(DataPaths, NamesMatchIgnoringCaseAndByCommonName) {
  unsetenv("ECOFOREST_DATA_DIR");
  const auto species = std::filesystem::path(ECOFOREST_DATA_DIR) / "species";
  EXPECT_EQ(resolveSpecies("Beech"), species / "beech.toml");
  EXPECT_EQ(resolveSpecies("hazel"), species / "shrub.toml");  // shrub.toml's common_names
  EXPECT_EQ(resolveSpecies("Common Hazel"), species / "shrub.toml");
  EXPECT_EQ(resolveScenario("VALLEY"), std::filesystem::path(ECOFOREST_DATA_DIR) / "valley.toml");
}

TEST(DataPaths, ANearMissSuggestsTheName) {
  unsetenv("ECOFOREST_DATA_DIR");
  auto message = [](auto resolve, const std::string& name) {
    try {
      resolve(name);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(resolveSpecies, "beeh").find("did you mean 'beech'?"), std::string::npos);
  EXPECT_NE(message(resolveSpecies, "hazle").find("did you mean 'hazel'?"), std::string::npos);
  EXPECT_NE(message(resolveScenario, "valey").find("did you mean 'valley'?"), std::string::npos);
  EXPECT_NE(message(resolveLSystem, "abop_1_24").find("did you mean"), std::string::npos);
  EXPECT_EQ(message(resolveSpecies, "baobab").find("did you mean"), std::string::npos);
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
