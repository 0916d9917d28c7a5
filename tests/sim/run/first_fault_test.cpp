#include "sim/run/first_fault.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace eco {
namespace {

// Faults spread over many blocks of rows, looked for side by side: always the first.
TEST(FirstFaulty, IsTheSmallestFaultyIndexOrTheCountWhenNone) {
  const std::size_t count = 1000000;
  std::vector<char> faulty(count, 0);
  EXPECT_EQ(firstFaulty(count, [&](std::size_t i) { return faulty[i] != 0; }), count);
  for (std::size_t i : {999999u, 700001u, 300007u, 65536u * 3 + 5}) faulty[i] = 1;
  EXPECT_EQ(firstFaulty(count, [&](std::size_t i) { return faulty[i] != 0; }), 65536u * 3 + 5);
  faulty[0] = 1;
  EXPECT_EQ(firstFaulty(count, [&](std::size_t i) { return faulty[i] != 0; }), 0u);
  EXPECT_EQ(firstFaulty(0, [](std::size_t) { return true; }), 0u);
}

}  // namespace
}  // namespace eco
