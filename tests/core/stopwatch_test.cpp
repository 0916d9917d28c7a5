#include "core/stopwatch.hpp"

#include <thread>

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(Stopwatch, CountsMillisecondsOfWallTime) {
  const auto start = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_GE(millisecondsSince(start), 20.0);
  EXPECT_LT(millisecondsSince(std::chrono::steady_clock::now()), 20.0);
}

}  // namespace
}  // namespace eco
