#include "sim/run/trees_file.hpp"

#include <cmath>
#include <cstring>
#include <functional>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "ecosystem_support.hpp"
#include "sealed_support.hpp"
#include "sim/run/checksummed_output.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

using test::OneHectare;

const char* kHeader =
    "id,species,x_m,y_m,z_m,age,height_m,crown_radius_m,crown_base_m,dbh_m,vigor,variant_seed\n";

TEST(TreesFile, ReadsATreesFileAndNumbersSpeciesInOrderOfAppearance) {
  const auto file = test::freshDirectory("trees_file_csv") / "year_0010.csv";
  test::writeFile(file, std::string(kHeader) +
                            "7,pine,10.500,20.250,412.000,12,6.500,1.200,2.500,0.0800,0.900,123\n"
                            "9,beech,1.000,2.000,400.000,3,0.400,0.100,0.000,0.0000,1.000,5\n"
                            "11,pine,3.000,4.000,401.000,40,20.000,3.000,12.000,0.3000,0.500,"
                            "4294967295\n");
  const TreeSnapshot s = readTreesCsv(file);
  ASSERT_EQ(s.trees.size(), 3u);
  EXPECT_EQ(s.speciesNames, (std::vector<std::string>{"pine", "beech"}));
  EXPECT_EQ(s.trees[0].id, 7u);
  EXPECT_EQ(s.trees[0].species, 0);
  EXPECT_DOUBLE_EQ(s.trees[0].north_m, 20.25);
  EXPECT_FLOAT_EQ(s.trees[0].height_m, 6.5f);
  EXPECT_FLOAT_EQ(s.trees[0].crownBase_m, 2.5f);
  EXPECT_EQ(s.trees[1].species, 1);
  EXPECT_EQ(s.trees[2].species, 0);
  EXPECT_EQ(s.trees[2].variantSeed, 4294967295u);  // 32 bits, exact in a spreadsheet
  // A seed beyond 32 bits is not one ecoforest wrote.
  test::writeFile(file, std::string(kHeader) +
                            "7,pine,10.500,20.250,412.000,12,6.500,1.200,2.500,0.0800,0.900,"
                            "4294967296\n");
  EXPECT_THROW(readTreesCsv(file), InputError);
}

TEST(TreesFile, AMalformedTreesFileNamesTheLine) {
  const auto file = test::freshDirectory("trees_file_bad") / "trees.csv";
  test::writeFile(
      file, std::string(kHeader) +
                "1,pine,1,2,3,4,5,0.6,0.7,0.08,0.9,10\n2,pine,1,2,x,4,5,0.6,0.7,0.08,0.9,10\n");
  try {
    readTreesCsv(file);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3);
  }
  test::writeFile(file, "id,name\n");
  EXPECT_THROW(readTreesCsv(file), InputError);
}

// A trees file is read back as untrusted input: each value a later command would turn into
// a NaN transform or a huge mesh is refused at its line.
TEST(TreesFile, TreesValuesOutOfRangeAreRefusedAtTheirLine) {
  const auto file = test::freshDirectory("trees_file_values") / "trees.csv";
  const std::string good = "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123";
  auto faultOf = [&](const std::string& row) {
    test::writeFile(file, std::string(kHeader) + good + "\n" + row + "\n");
    try {
      readTreesCsv(file);
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, 3) << row;
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(faultOf("8,pine,nan,20,412,12,6.5,1.2,2.5,0.08,0.9,1").find("numbers"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,inf,412,12,6.5,1.2,2.5,0.08,0.9,1").find("numbers"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,6.5,1.2,2.5,0.08,0.9,1,extra").find("numbers"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pi/ne,1,2,412,12,6.5,1.2,2.5,0.08,0.9,1").find("not a species name"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,-1,6.5,1.2,2.5,0.08,0.9,1").find("age -1"), std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,1e30,1.2,2.5,0.08,0.9,1").find("height"), std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,6.5,-1,2.5,0.08,0.9,1").find("crown radius"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,6.5,1.2,9,0.08,0.9,1").find("crown base"),
            std::string::npos);
  EXPECT_NE(faultOf("8,pine,1,2,412,12,6.5,1.2,2.5,0.08,1.5,1").find("vigor"), std::string::npos);
  EXPECT_EQ(faultOf(good), "no error");
}

// A file of several megabytes is read in stretches side by side: the trees come back in
// the file's order, species numbered by first appearance across the stretches, empty lines
// skipped, and of two bad rows far apart the first is reported at its line.
TEST(TreesFile, ALongTreesFileReadsAsItsLinesInOrder) {
  const auto file = test::freshDirectory("trees_file_long") / "trees.csv";
  constexpr int kRows = 60000;  // about 3 MB: a few stretches of a megabyte
  auto rowOf = [](int id, const char* species) {
    return std::to_string(id) + "," + species + ",1.5,2.5,400,7,6.5,1.2,2.5,0.08,0.9," +
           std::to_string(id % 1000) + "\n";
  };
  auto speciesOf = [](int id) { return id < 20000 ? "beech" : id < 45000 ? "pine" : "maple"; };
  std::string text = kHeader;
  std::vector<int> lineOf(kRows + 1);
  int line = 1;
  for (int id = 1; id <= kRows; ++id) {
    if (id % 7001 == 0) {
      text += "\n";  // an empty line between rows
      ++line;
    }
    text += rowOf(id, speciesOf(id));
    lineOf[id] = ++line;
  }
  ASSERT_GT(text.size(), std::size_t{2} << 20);
  test::writeFile(file, text);
  const TreeSnapshot s = readTreesCsv(file);
  ASSERT_EQ(s.trees.size(), static_cast<std::size_t>(kRows));
  EXPECT_EQ(s.speciesNames, (std::vector<std::string>{"beech", "pine", "maple"}));
  for (int id = 1; id <= kRows; ++id) {
    const TreeRow& tree = s.trees[static_cast<std::size_t>(id - 1)];
    ASSERT_EQ(tree.id, static_cast<std::uint64_t>(id));
    ASSERT_EQ(s.speciesNames[static_cast<std::size_t>(tree.species)], speciesOf(id));
    ASSERT_EQ(tree.variantSeed, static_cast<std::uint32_t>(id % 1000));
  }
  // Only the maples kept: the species are still the file's, in its order.
  const TreeSnapshot maples = readTreesCsv(
      file, [&](const TreeRow& tree) { return s.speciesNames[tree.species] == "maple"; });
  EXPECT_EQ(maples.speciesNames, s.speciesNames);
  ASSERT_EQ(maples.trees.size(), static_cast<std::size_t>(kRows - 45000 + 1));
  EXPECT_EQ(maples.trees.front().id, 45000u);
  for (const TreeRow& tree : maples.trees) ASSERT_EQ(maples.speciesNames[tree.species], "maple");
  // Two bad rows, one near the end and one in the middle: the middle one is reported.
  auto bad = [&](int id) {
    const std::string good = rowOf(id, speciesOf(id));
    const std::size_t at = text.find("\n" + good) + 1;
    text.replace(at, good.size(), std::to_string(id) + ",pine,x\n");
  };
  bad(55000);
  bad(30000);
  test::writeFile(file, text);
  // Also when the rows are filtered: a row not kept is checked all the same.
  for (const TreeFilter& keep : {TreeFilter{}, TreeFilter{[](const TreeRow&) { return false; }}})
    try {
      readTreesCsv(file, keep);
      ADD_FAILURE() << "a bad row was read";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, lineOf[30000]);
    }
}

// Both formats read back what was written: CSV to its decimals, binary exactly.
TEST_F(OneHectare, TheTreesReadersReadWhatTheWritersWrote) {
  ecosystem.plant(0, 12.0, 33.0, 40);
  ecosystem.plant(0, 71.5, 8.25, 3);
  ecosystem.step();  // the sites are under a year's canopy
  const auto folder = test::freshDirectory("trees_file_round_trip");
  const Plants& p = ecosystem.plants();
  const std::vector<PlantSite> sites = ecosystem.sitesOf(p);
  for (const SnapshotFormat format : {SnapshotFormat::Csv, SnapshotFormat::Binary}) {
    const auto file = folder / ("year_0001" + std::string(extensionOf(format)));
    writeTrees(file, ecosystem, p, format);
    EXPECT_EQ(snapshotFormatOf(file), format);
    const TreeSnapshot snapshot = readTrees(file);
    const double decimals = format == SnapshotFormat::Csv ? 5e-4 : 0.0;
    ASSERT_EQ(snapshot.trees.size(), p.size());
    EXPECT_EQ(snapshot.speciesNames, std::vector<std::string>{"t"});
    for (std::size_t i = 0; i < p.size(); ++i) {
      const TreeRow& row = snapshot.trees[i];
      EXPECT_EQ(row.id, p.id[i]);
      EXPECT_NEAR(row.east_m, p.east_m[i], decimals);
      EXPECT_NEAR(row.north_m, p.north_m[i], decimals);
      EXPECT_EQ(row.age_years, p.age_years[i]);
      EXPECT_NEAR(row.height_m, p.height_m[i], decimals);
      EXPECT_NEAR(row.crownBase_m, p.crownBase_m[i], decimals);
      EXPECT_NEAR(row.dbh_m, p.dbh_m[i], decimals);
      EXPECT_EQ(row.variantSeed, ecosystem.variantSeedOf(p.id[i]));
      EXPECT_NEAR(row.ground_m, ecosystem.groundOf(p, i), decimals);
      const double siteDecimals = format == SnapshotFormat::Csv ? 5e-3 : 0.0;
      EXPECT_NEAR(row.site.light.x, sites[i].light.x, siteDecimals);
      EXPECT_NEAR(row.site.light.y, sites[i].light.y, siteDecimals);
      EXPECT_NEAR(row.site.wind.x, sites[i].wind.x, siteDecimals);
      EXPECT_NEAR(row.site.wind.y, sites[i].wind.y, siteDecimals);
    }
  }
}

// The site columns (light and wind toward east and north) read back; a file of an earlier
// version without them reads as unshaped trees (the tests above); a direction longer than 1
// is refused at its line.
TEST(TreesFile, TheSiteColumnsReadBackAndAreChecked) {
  const auto file = test::freshDirectory("trees_file_site") / "year_0010.csv";
  const std::string header = std::string(kTreesCsvHeader) + "\n";
  test::writeFile(file, header +
                            "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123,"
                            "0.60,-0.25,0.00,0.71\n");
  const TreeSnapshot s = readTreesCsv(file);
  ASSERT_EQ(s.trees.size(), 1u);
  EXPECT_FLOAT_EQ(s.trees[0].site.light.x, 0.6f);
  EXPECT_FLOAT_EQ(s.trees[0].site.light.y, -0.25f);
  EXPECT_FLOAT_EQ(s.trees[0].site.wind.y, 0.71f);
  for (const char* row : {"7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123,0.9,0.9,0,0",
                          "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123,0,0,1.2,0",
                          "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123,0,0,0",
                          "7,pine,10.5,20.25,412,12,6.5,1.2,2.5,0.08,0.9,123"}) {
    test::writeFile(file, header + row + "\n");
    try {
      readTreesCsv(file);
      ADD_FAILURE() << row;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, 2) << row;
    }
  }
}

TEST_F(OneHectare, ALargeSnapshotIsWrittenAndReadInBatchesInOrder) {
  // More rows than one batch of encoded chunks (64 x 16,384) and than one batch the binary
  // reader decodes (2^20), and more than the CSV reader's batch of 64 MiB, so batches meet.
  const std::size_t n = 64 * 16384 + 1000;
  Plants p;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.id[i] = i + 1;
    p.age_years[i] = static_cast<std::int32_t>(i % 97);
  }
  auto keep = [](const TreeRow& tree) { return tree.age_years % 7 == 3 || tree.id > n - 5; };
  const auto folder = test::freshDirectory("trees_file_batches");
  for (const SnapshotFormat format : {SnapshotFormat::Csv, SnapshotFormat::Binary}) {
    const auto file = folder / ("year_0001" + std::string(extensionOf(format)));
    writeTrees(file, ecosystem, p, format);
    if (format == SnapshotFormat::Csv) {
      ASSERT_GT(std::filesystem::file_size(file), 64u << 20);
    }
    const TreeSnapshot snapshot = readTrees(file);
    ASSERT_EQ(snapshot.trees.size(), n);
    // Room for the rows: no fewer, and at most the header and a line cut between parts more.
    EXPECT_GE(treeRowsAtMost(file), n);
    EXPECT_LE(treeRowsAtMost(file), n + 2);
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_EQ(snapshot.trees[i].id, i + 1);
      ASSERT_EQ(snapshot.trees[i].age_years, static_cast<int>(i % 97));
    }
    // Filtered: the rows kept, in order, and only those held.
    const TreeSnapshot kept = readTrees(file, keep);
    std::vector<std::uint64_t> expected;
    for (const TreeRow& tree : snapshot.trees)
      if (keep(tree)) expected.push_back(tree.id);
    std::vector<std::uint64_t> ids;
    for (const TreeRow& tree : kept.trees) ids.push_back(tree.id);
    EXPECT_EQ(ids, expected);
    EXPECT_EQ(kept.speciesNames, snapshot.speciesNames);
    EXPECT_EQ(kept.trees.capacity(), kept.trees.size());
    // Batch by batch, in order: the same rows, more than one batch of them.
    std::vector<std::uint64_t> batched;
    int batches = 0;
    readTreesInBatches(file, keep,
                       [&](std::span<const TreeRow> rows, const std::vector<std::string>& names) {
                         ++batches;
                         EXPECT_EQ(names, snapshot.speciesNames);
                         for (const TreeRow& tree : rows) batched.push_back(tree.id);
                       });
    EXPECT_EQ(batched, expected);
    EXPECT_GE(batches, 2);
    // And written out batch by batch as CSV: the CSV snapshot's bytes (written first).
    const auto copy = folder / "copy.csv";
    TreesCsvWriter writer(copy);
    readTreesInBatches(file, {},
                       [&](std::span<const TreeRow> rows, const std::vector<std::string>& names) {
                         writer.write(rows, names);
                       });
    writer.commit();
    EXPECT_TRUE(test::readFile(copy) == test::readFile(folder / "year_0001.csv"));
  }
  // A bad row in the CSV reader's second batch is reported at its line, kept or not.
  const auto file = folder / "year_0001.csv";
  std::string text = test::readFile(file);
  const std::size_t row = n - 10;  // line row + 2
  std::size_t at = 0;
  for (std::size_t line = 0; line < row + 1; ++line) at = text.find('\n', at) + 1;
  text.insert(text.find(',', text.find(',', at) + 1) + 1, "x");  // x_m is not a number
  test::writeFile(file, text);
  for (const TreeFilter& filter : {TreeFilter{}, TreeFilter{keep}}) {
    try {
      readTrees(file, filter);
      ADD_FAILURE() << "a bad row was read";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, static_cast<int>(row + 2));
    }
  }
}

// A binary snapshot written out as CSV (what `export RUN --out trees.csv` does) has the
// bytes of the CSV snapshot of the same plants, in fewer bytes.
TEST_F(OneHectare, ABinarySnapshotWrittenAsCsvIsTheCsvSnapshot) {
  for (int i = 0; i < 40; ++i) ecosystem.plant(0, 3.0 + 2.13 * i, 87.0 - 2.01 * i, 5 + i);
  ecosystem.step();
  const auto folder = test::freshDirectory("trees_file_convert");
  writeTrees(folder / "direct.csv", ecosystem, ecosystem.plants(), SnapshotFormat::Csv);
  writeTrees(folder / "year.bin", ecosystem, ecosystem.plants(), SnapshotFormat::Binary);
  writeTrees(folder / "converted.csv", readTrees(folder / "year.bin"), SnapshotFormat::Csv);
  EXPECT_EQ(test::readFile(folder / "converted.csv"), test::readFile(folder / "direct.csv"));
  EXPECT_LT(std::filesystem::file_size(folder / "year.bin"),
            std::filesystem::file_size(folder / "direct.csv") * 3 / 4);
}

std::string binaryFaultOf(const std::filesystem::path& file) {
  try {
    readTreesBinary(file);
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, file.string());
    return e.what();
  }
  return "no error";
}

// A binary snapshot is untrusted input: a flipped or missing byte fails its checksum,
// another file or version is named as such.
TEST(TreesFile, ACorruptTruncatedOrForeignBinaryFileIsRefused) {
  const auto file = test::freshDirectory("trees_file_binary_bad") / "year_0010.bin";
  TreeSnapshot snapshot;
  snapshot.speciesNames = {"beech", "pine"};
  for (std::uint64_t id = 1; id <= 100; ++id) {
    TreeRow& tree = snapshot.trees.emplace_back();
    tree.id = id;
    tree.species = static_cast<int>(id % 2);
    tree.height_m = 0.1f * static_cast<float>(id);
  }
  writeTrees(file, snapshot, SnapshotFormat::Binary);
  const std::string bytes = test::readFile(file);
  EXPECT_EQ(binaryFaultOf(file), "no error");
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x10;
  test::writeFile(file, flipped);
  EXPECT_NE(binaryFaultOf(file).find("checksum"), std::string::npos);
  test::writeFile(file, bytes.substr(0, bytes.size() - 30));
  EXPECT_NE(binaryFaultOf(file).find("checksum"), std::string::npos);
  test::writeFile(file, std::string(kTreesCsvHeader) + "\n");
  EXPECT_NE(binaryFaultOf(file).find("not a binary trees file"), std::string::npos);
  std::string otherVersion = bytes;
  otherVersion[8 + 15] = 9;  // the version after the magic's length and 15 letters
  test::writeFile(file, otherVersion);
  EXPECT_NE(binaryFaultOf(file).find("another version"), std::string::npos);
  test::writeFile(file, "");
  EXPECT_NE(binaryFaultOf(file).find("not a binary trees file"), std::string::npos);
}

// A binary snapshot of version 1 (the same layout, checksummed by FNV-1a) reads as it did;
// its bytes under version 2's hash are corrupt.
TEST(TreesFile, ABinarySnapshotOfVersionOneIsStillRead) {
  const auto file = test::freshDirectory("trees_file_binary_v1") / "year_0010.bin";
  TreeSnapshot snapshot;
  snapshot.speciesNames = {"beech"};
  for (std::uint64_t id = 1; id <= 50; ++id)
    snapshot.trees.push_back({.id = id, .east_m = 0.5 * static_cast<double>(id), .height_m = 2.0f});
  writeTrees(file, snapshot, SnapshotFormat::Binary);
  const std::string bytes = test::readFile(file);
  test::writeFile(file, test::resealed(bytes, "ECOFOREST-TREES", 1, BlockHash::Fnv1a));
  const TreeSnapshot back = readTrees(file);
  ASSERT_EQ(back.trees.size(), 50u);
  EXPECT_EQ(back.trees[49].id, 50u);
  EXPECT_EQ(back.trees[49].east_m, 25.0);
  test::writeFile(file, test::resealed(bytes, "ECOFOREST-TREES", 1, BlockHash::Xxh3));
  EXPECT_NE(binaryFaultOf(file).find("checksum"), std::string::npos);
}

// Values a later command would turn into NaN transforms or huge meshes are refused at the
// first row that has one, even in a file whose checksum holds (one made on purpose).
TEST(TreesFile, BinaryValuesOutOfRangeAreRefusedAtTheFirstRow) {
  const auto file = test::freshDirectory("trees_file_binary_values") / "year_0010.bin";
  auto faultOf = [&](const std::function<void(TreeRow&)>& spoil) {
    TreeSnapshot snapshot;
    snapshot.speciesNames = {"beech"};
    for (std::uint64_t id = 1; id <= 140000; ++id) {  // several blocks read side by side
      TreeRow& tree = snapshot.trees.emplace_back();
      tree.id = id;
      tree.height_m = 10.0f;
    }
    spoil(snapshot.trees[100000]);
    spoil(snapshot.trees[139000]);
    writeTrees(file, snapshot, SnapshotFormat::Binary);
    return binaryFaultOf(file);
  };
  EXPECT_EQ(faultOf([](TreeRow&) {}), "no error");
  const std::string firstRow = "row 100001 (tree 100001)";
  EXPECT_NE(faultOf([](TreeRow& t) { t.east_m = std::nan(""); }).find(firstRow + ": a position"),
            std::string::npos);
  EXPECT_NE(faultOf([](TreeRow& t) { t.ground_m = INFINITY; }).find("position"), std::string::npos);
  EXPECT_NE(faultOf([](TreeRow& t) { t.species = 1; }).find(firstRow + ": species 2 of 1"),
            std::string::npos);
  EXPECT_NE(faultOf([](TreeRow& t) { t.height_m = 1e30f; }).find(firstRow + ": height"),
            std::string::npos);
  EXPECT_NE(faultOf([](TreeRow& t) { t.vigor = -1.0f; }).find("vigor"), std::string::npos);
  EXPECT_NE(faultOf([](TreeRow& t) { t.id = 0; }).find("id 0"), std::string::npos);
  EXPECT_NE(faultOf([](TreeRow& t) {
              t.site.wind = {1.0f, 1.0f};
            }).find("wind"),
            std::string::npos);
}

TEST(TreesFile, ABinaryFileWithABadSpeciesNameOrLengthIsRefused) {
  const auto file = test::freshDirectory("trees_file_binary_names") / "year_0010.bin";
  TreeSnapshot snapshot;
  snapshot.speciesNames = {"be/ech"};
  snapshot.trees.emplace_back().id = 1;
  writeTrees(file, snapshot, SnapshotFormat::Binary);
  EXPECT_NE(binaryFaultOf(file).find("not a species name"), std::string::npos);
  // A row count that does not fit the bytes, sealed with a valid checksum.
  snapshot.speciesNames = {"beech"};
  writeTrees(file, snapshot, SnapshotFormat::Binary);
  std::string bytes = test::readFile(file);
  std::string body = bytes.substr(0, bytes.size() - 8);
  const std::size_t countAt = body.size() - 66 - 8;  // one record of 66 bytes
  const std::uint64_t count = 3;
  std::memcpy(body.data() + countAt, &count, sizeof count);
  const std::uint64_t checksum = blockChecksum(body, BlockHash::Xxh3);
  test::writeFile(file, body + std::string(reinterpret_cast<const char*>(&checksum), 8));
  EXPECT_NE(binaryFaultOf(file).find("length"), std::string::npos);
}

}  // namespace
}  // namespace eco
