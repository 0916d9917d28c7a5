#include "sim/run/checkpoint.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "sealed_support.hpp"
#include "sim/run/checksummed_output.hpp"
#include "test_files.hpp"

namespace eco {
namespace {

Checkpoint sample() {
  Checkpoint c;
  c.scenarioHash = 0x1234;
  c.programVersion = "1.2.3";
  c.state.year = 17;
  c.state.nextId = 99;
  c.state.plants.resize(3);
  for (std::size_t i = 0; i < 3; ++i) {
    c.state.plants.id[i] = 5 + i;
    c.state.plants.height_m[i] = 1.5f * i;
    c.state.plants.stressYears[i] = static_cast<std::uint8_t>(i);
  }
  c.state.plants.growthFactor = {1.0f, 0.9f, 0.7f};
  c.stats.push_back({.year = 17,
                     .species = 0,
                     .alive = 3,
                     .born = 1,
                     .died = 2,
                     .meanHeight_m = 0.75,
                     .stemsPerHa = 2.0,
                     .basalArea_m2PerHa = 0.01,
                     .sdi = 1.5,
                     .coverFraction = 0.2});
  return c;
}

std::string errorOf(const std::filesystem::path& file, std::uint64_t hash) {
  try {
    readCheckpoint(file, hash);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Checkpoint, RoundTripsTheState) {
  const auto file = test::freshDirectory("checkpoint") / "checkpoint.bin";
  writeCheckpoint(file, sample());
  const Checkpoint back = readCheckpoint(file, 0x1234);
  EXPECT_EQ(back.programVersion, "1.2.3");
  EXPECT_EQ(back.state.year, 17);
  EXPECT_EQ(back.state.nextId, 99u);
  EXPECT_EQ(back.state.plants.id, sample().state.plants.id);
  EXPECT_EQ(back.state.plants.height_m, sample().state.plants.height_m);
  EXPECT_EQ(back.state.plants.stressYears, sample().state.plants.stressYears);
  EXPECT_EQ(back.state.plants.growthFactor, sample().state.plants.growthFactor);
  ASSERT_EQ(back.stats.size(), 1u);
  EXPECT_EQ(back.stats[0].died, 2);
  EXPECT_EQ(back.stats[0].coverFraction, 0.2);
  EXPECT_EQ(back.stats[0].sdi, 1.5);
}

TEST(Checkpoint, AStateOfManyBlocksIsWrittenThroughWithItsChecksum) {
  // 300,000 plants: columns of 0.3 to 2.4 MB, so whole 1 MiB checksum blocks and partial
  // ones meet at every column boundary of the written-through file.
  Checkpoint big = sample();
  const std::size_t n = 300000;
  big.state.plants.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    big.state.plants.id[i] = 1000 + i;
    big.state.plants.height_m[i] = 0.001f * static_cast<float>(i % 5000);
    big.state.plants.age_years[i] = static_cast<std::uint16_t>(i % 300);
  }
  const auto file = test::freshDirectory("checkpoint_big") / "checkpoint.bin";
  AtomicFile out(file);
  writeCheckpoint(out, big.scenarioHash, big.programVersion, big.state, big.stats);
  out.commit();
  const std::string bytes = test::readFile(file);
  ASSERT_GT(bytes.size(), std::size_t{12} << 20);  // 42 bytes a plant: 12 blocks and a part
  // The stored checksum is that of the whole body, as if it had been made in memory.
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - sizeof stored, sizeof stored);
  EXPECT_EQ(stored,
            blockChecksum(std::string_view(bytes).substr(0, bytes.size() - 8), BlockHash::Xxh3));
  const Checkpoint back = readCheckpoint(file, 0x1234);
  EXPECT_EQ(back.state.plants.id, big.state.plants.id);
  EXPECT_EQ(back.state.plants.height_m, big.state.plants.height_m);
  EXPECT_EQ(back.state.plants.age_years, big.state.plants.age_years);
  EXPECT_EQ(back.stats.size(), 1u);
}

TEST(Checkpoint, RefusesCorruptTruncatedForeignAndMissingFiles) {
  const auto folder = test::freshDirectory("checkpoint_bad");
  const auto file = folder / "checkpoint.bin";
  writeCheckpoint(file, sample());
  std::string bytes = test::readFile(file);

  EXPECT_NE(errorOf(file, 0x9999).find("another scenario"), std::string::npos);
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x40;
  test::writeFile(file, flipped);
  EXPECT_NE(errorOf(file, 0x1234).find("corrupt"), std::string::npos);
  test::writeFile(file, bytes.substr(0, bytes.size() - 20));
  EXPECT_NE(errorOf(file, 0x1234).find("corrupt"), std::string::npos);
  test::writeFile(file, "PK\x03\x04 a zip file, not ours");
  EXPECT_NE(errorOf(file, 0x1234).find("not an ecoforest checkpoint"), std::string::npos);
  EXPECT_NE(errorOf(folder / "none.bin", 0x1234).find("cannot open"), std::string::npos);
}

// A checkpoint of format version 7 (the same layout, checksummed by FNV-1a) resumes as it
// did; its bytes under version 8's hash are corrupt.
TEST(Checkpoint, ACheckpointOfVersionSevenIsStillRead) {
  const auto file = test::freshDirectory("checkpoint_v7") / "checkpoint.bin";
  writeCheckpoint(file, sample());
  const std::string bytes = test::readFile(file);
  test::writeFile(file, test::resealed(bytes, "ECOFOREST-CHECKPOINT", 7, BlockHash::Fnv1a));
  const Checkpoint back = readCheckpoint(file, 0x1234);
  EXPECT_EQ(back.state.year, 17);
  EXPECT_EQ(back.state.plants.id, sample().state.plants.id);
  test::writeFile(file, test::resealed(bytes, "ECOFOREST-CHECKPOINT", 7, BlockHash::Xxh3));
  EXPECT_NE(errorOf(file, 0x1234).find("corrupt"), std::string::npos);
  test::writeFile(file, test::resealed(bytes, "ECOFOREST-CHECKPOINT", 6, BlockHash::Fnv1a));
  EXPECT_NE(errorOf(file, 0x1234).find("another version"), std::string::npos);
}

const Grid kGrid{10, 10, 2.0, 2.0};
const CheckpointLimits kLimits{kGrid, 1, 40};

// A checkpoint whose plants stand on a 10 x 10 grid of 2 m cells, with one species.
Checkpoint fitting() {
  Checkpoint c = sample();
  Plants& p = c.state.plants;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.east_m[i] = 3.0f + 4.0f * i;
    p.north_m[i] = 5.0f;
    p.age_years[i] = static_cast<std::uint16_t>(i);
    p.vigor[i] = 0.5f;
    p.alive[i] = 1;
  }
  return c;
}
std::string faultOf(const Checkpoint& c) {
  try {
    checkCheckpoint(c, kLimits, "checkpoint.bin");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Checkpoint, AFittingCheckpointIsAccepted) {
  EXPECT_EQ(faultOf(fitting()), "no error");
}

// The values an attacker or a broken disk can put behind a good checksum: each is refused
// with a message naming it, never used.
TEST(Checkpoint, CraftedValuesAreRefused) {
  auto crafted = [](auto change) {
    Checkpoint c = fitting();
    change(c);
    return faultOf(c);
  };
  EXPECT_NE(crafted([](Checkpoint& c) {
              c.state.plants.east_m[1] = 1e30f;
            }).find("plant 2 (id 6): position (1e+30, 5) m is not on the terrain"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) { c.state.year = -100000; }).find("year -100000"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) { c.state.year = 41; }).find("run's 40 years"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) { c.state.plants.age_years[0] = 65535; }).find("age 65535"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) {
              c.state.plants.height_m[2] = std::nanf("");
            }).find("height nan m"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) {
              c.state.plants.species[0] = 7;
            }).find("species index 7, but the scenario has 1 species"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) {
              c.state.plants.id[2] = 5;
            }).find("plants 1 and 3 have the same id 5"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) { c.state.plants.id[1] = 0; }).find("plant 2 has id 0"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) { c.state.nextId = 6; }).find("below the next id 6"),
            std::string::npos);
  // The plants are in order of place: ids out of order are no fault.
  EXPECT_EQ(crafted([](Checkpoint& c) { std::swap(c.state.plants.id[0], c.state.plants.id[2]); }),
            "no error");
  EXPECT_NE(
      crafted([](Checkpoint& c) { c.state.plants.growthFactor[0] = 0.0f; }).find("growth factor 0"),
      std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) { c.state.plants.alive[0] = 9; }).find("alive flag 9"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) {
              c.stats[0].species = 3;
            }).find("statistics row 1: species index 3"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) { c.stats[0].year = 18; }).find("statistics row 1: year 18"),
            std::string::npos);
  EXPECT_NE(crafted([](Checkpoint& c) {
              c.stats[0].sdi = -std::numeric_limits<double>::infinity();
            }).find("statistics row 1"),
            std::string::npos);
  EXPECT_NE(
      crafted([](Checkpoint& c) { c.state.plants.east_m[0] = 1e30f; }).find("start the run afresh"),
      std::string::npos);
}

// The first fault in plant order is the one reported, whatever the thread count: plants
// beyond one parallel block.
TEST(Checkpoint, TheFirstFaultyPlantIsReported) {
  Checkpoint c = fitting();
  Plants& p = c.state.plants;
  const std::size_t n = 200000;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.id[i] = i + 1;
    p.east_m[i] = 1.0f;
    p.north_m[i] = 1.0f;
    p.vigor[i] = 0.5f;
    p.growthFactor[i] = 1.0f;
    p.age_years[i] = 0;
  }
  c.state.nextId = n + 1;
  p.height_m[150000] = -1.0f;
  p.height_m[190000] = -1.0f;
  EXPECT_NE(faultOf(c).find("plant 150001 (id 150001)"), std::string::npos) << faultOf(c);
}

}  // namespace
}  // namespace eco
