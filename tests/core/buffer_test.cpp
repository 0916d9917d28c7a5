#include "core/buffer.hpp"

#include <cstdint>

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(Buffer, KeepsWhatItHoldsAsAVectorDoes) {
  Buffer<std::uint32_t> buffer;
  for (std::uint32_t i = 0; i < 1000; ++i) buffer.push_back(i * 3);
  buffer.resize(1200);  // the new values are left to be written
  buffer.resize(10);
  ASSERT_EQ(buffer.size(), 10u);
  for (std::uint32_t i = 0; i < 10; ++i) EXPECT_EQ(buffer[i], i * 3);
  const Buffer<std::uint32_t> copy = buffer;
  EXPECT_EQ(copy, buffer);
}

TEST(Buffer, AWorkingBufferThatShrinksAndGrowsBackKeepsItsStorage) {
  // What the simulation's working arrays rely on, kept from year to year: a smaller year
  // and a larger one within the room already taken allocate nothing.
  Buffer<double> buffer(800);
  const double* storage = buffer.data();
  buffer.resize(100);
  buffer.resize(800);
  EXPECT_EQ(buffer.data(), storage);
  EXPECT_EQ(buffer.size(), 800u);
}

TEST(Buffer, AWorkingArrayGrowingPastItsRoomTakesNewRoomWithAQuarterMore) {
  Buffer<double> buffer(800);
  resizeForOverwrite(buffer, 600);  // within its room: the same storage
  EXPECT_EQ(buffer.size(), 600u);
  EXPECT_EQ(buffer.capacity(), 800u);
  resizeForOverwrite(buffer, 1000);
  EXPECT_EQ(buffer.size(), 1000u);
  EXPECT_EQ(buffer.capacity(), 1250u);
  // A plain vector's new elements are value-initialised, as its resize() makes them.
  std::vector<int> values{1, 2, 3};
  resizeForOverwrite(values, 8);
  EXPECT_EQ(values, std::vector<int>(8, 0));
}

}  // namespace
}  // namespace eco
