#include "sim/run_folder.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

const char* kHeader =
    "id,species,x_m,y_m,z_m,age,height_m,crown_radius_m,dbh_m,vigor,variant_seed\n";

TEST(RunFolder, ReadsATreesFileAndNumbersSpeciesInOrderOfAppearance) {
  const auto file = test::freshDirectory("run_folder_csv") / "year_0010.csv";
  test::writeFile(
      file, std::string(kHeader) +
                "7,pine,10.500,20.250,412.000,12,6.500,1.200,0.0800,0.900,123\n"
                "9,beech,1.000,2.000,400.000,3,0.400,0.100,0.0000,1.000,5\n"
                "11,pine,3.000,4.000,401.000,40,20.000,3.000,0.3000,0.500,18446744073709551615\n");
  const TreeSnapshot s = readTreesCsv(file);
  ASSERT_EQ(s.trees.size(), 3u);
  EXPECT_EQ(s.speciesNames, (std::vector<std::string>{"pine", "beech"}));
  EXPECT_EQ(s.trees[0].id, 7u);
  EXPECT_EQ(s.trees[0].species, 0);
  EXPECT_DOUBLE_EQ(s.trees[0].north_m, 20.25);
  EXPECT_FLOAT_EQ(s.trees[0].height_m, 6.5f);
  EXPECT_EQ(s.trees[1].species, 1);
  EXPECT_EQ(s.trees[2].species, 0);
  EXPECT_EQ(s.trees[2].variantSeed, 18446744073709551615ull);
}

TEST(RunFolder, AMalformedTreesFileNamesTheLine) {
  const auto file = test::freshDirectory("run_folder_bad") / "trees.csv";
  test::writeFile(file,
                  std::string(kHeader) + "1,pine,1,2,3,4,5,6,7,8,9\n2,pine,1,2,x,4,5,6,7,8,9\n");
  try {
    readTreesCsv(file);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3);
  }
  test::writeFile(file, "id,name\n");
  EXPECT_THROW(readTreesCsv(file), InputError);
}

TEST(RunFolder, AFolderWithoutRunJsonIsNotARun) {
  const auto dir = test::freshDirectory("run_folder_none");
  EXPECT_THROW(openRunFolder(dir), InputError);
  EXPECT_THROW(openRunFolder(dir / "missing"), InputError);
}

}  // namespace
}  // namespace eco
