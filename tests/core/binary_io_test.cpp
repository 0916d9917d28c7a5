#include "core/binary_io.hpp"

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(BinaryIo, ValuesStringsAndVectorsRoundTrip) {
  BinaryWriter w;
  w.put<std::int32_t>(-7);
  w.putString("hello");
  w.putVector(std::vector<float>{1.5f, 2.5f});
  w.put<double>(0.25);
  BinaryReader r(w.bytes());
  EXPECT_EQ(r.get<std::int32_t>(), -7);
  EXPECT_EQ(r.getString(), "hello");
  std::vector<float> v;
  r.getVector(v);
  EXPECT_EQ(v, (std::vector<float>{1.5f, 2.5f}));
  EXPECT_EQ(r.get<double>(), 0.25);
  EXPECT_TRUE(r.atEnd());
  EXPECT_FALSE(r.failed());
}

TEST(BinaryIo, ReadingPastTheEndFailsWithoutCrashing) {
  BinaryWriter w;
  w.putVector(std::vector<std::uint64_t>{1, 2, 3});
  const std::string truncated = w.bytes().substr(0, w.bytes().size() - 1);
  BinaryReader r(truncated);
  std::vector<std::uint64_t> v;
  r.getVector(v);
  EXPECT_TRUE(r.failed());
  EXPECT_TRUE(v.empty());
  EXPECT_EQ(r.get<std::uint64_t>(), 0u);
  // A huge claimed length is refused rather than allocated.
  BinaryWriter lie;
  lie.put<std::uint64_t>(1ull << 60);
  BinaryReader r2(lie.bytes());
  r2.getVector(v);
  EXPECT_TRUE(r2.failed());
}

TEST(BinaryIo, EmptyVectorsRoundTrip) {
  BinaryWriter w;
  w.putVector(std::vector<float>{});
  w.put<std::int32_t>(7);
  BinaryReader r(w.bytes());
  std::vector<float> v{1.0f};
  r.getVector(v);
  EXPECT_TRUE(v.empty());
  EXPECT_EQ(r.get<std::int32_t>(), 7);
  EXPECT_FALSE(r.failed());
  EXPECT_TRUE(r.atEnd());
}

}  // namespace
}  // namespace eco
