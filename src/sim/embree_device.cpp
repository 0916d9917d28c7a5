#include "sim/embree_device.hpp"

#include "core/error.hpp"

namespace eco {

EmbreeDevice::EmbreeDevice() {
  device = rtcNewDevice(nullptr);
  if (device == nullptr) throw InternalError("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(
      device,
      [](void* self, RTCError, const char* message) {
        auto* d = static_cast<EmbreeDevice*>(self);
        std::lock_guard lock(d->mutex);
        if (d->error.empty()) d->error = message ? message : "unknown error";
      },
      this);
}

EmbreeDevice::~EmbreeDevice() {
  rtcReleaseDevice(device);
}

void EmbreeDevice::check(const char* what) {
  std::lock_guard lock(mutex);
  if (!error.empty()) {
    std::string message = "Embree: " + std::string(what) + ": " + error;
    error.clear();
    throw InternalError(message);
  }
}

EmbreeDevice& embree() {
  static EmbreeDevice device;
  return device;
}

}  // namespace eco
