#include "sim/run/checkpoint.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
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
    c.state.plants.stressYears[i] = static_cast<std::uint16_t>(i);
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

}  // namespace
}  // namespace eco
