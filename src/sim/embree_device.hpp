// The one Embree device of the process. Embree reports errors through a callback; the
// device keeps the first message and check() turns it into an exception after the call
// that failed.
#pragma once

#include <mutex>
#include <string>

#include <embree3/rtcore.h>

namespace eco {

struct EmbreeDevice {
  RTCDevice device = nullptr;
  std::mutex mutex;
  std::string error;

  EmbreeDevice();
  ~EmbreeDevice();
  EmbreeDevice(const EmbreeDevice&) = delete;
  EmbreeDevice& operator=(const EmbreeDevice&) = delete;

  // Throws InternalError naming `what` if Embree reported an error since the last check.
  void check(const char* what);
};

EmbreeDevice& embree();

}  // namespace eco
