#include "sim/embree_device.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace eco {
namespace {

TEST(EmbreeDevice, ReportedErrorsBecomeExceptionsOnce) {
  EmbreeDevice& device = embree();
  EXPECT_NO_THROW(device.check("nothing"));
  RTCGeometry bad = rtcNewGeometry(device.device, static_cast<RTCGeometryType>(999));
  EXPECT_EQ(bad, nullptr);
  EXPECT_THROW(device.check("making a geometry of no type"), InternalError);
  EXPECT_NO_THROW(device.check("after the error was reported"));
}

}  // namespace
}  // namespace eco
