#include "sim/embree_device.hpp"

#include <algorithm>

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

RTCGeometry newTerrainGeometry(const Terrain& terrain,
                               const std::function<glm::vec3(int x, int y)>& position) {
  const Grid& g = terrain.grid;
  EmbreeDevice& device = embree();
  RTCGeometry mesh = rtcNewGeometry(device.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), g.cellCount()));
  const std::size_t quads =
      static_cast<std::size_t>(std::max(g.width - 1, 0)) * std::max(g.height - 1, 0);
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), 2 * quads));
  device.check("allocating the terrain mesh");
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      glm::vec3 p = position(x, y);
      std::copy(&p.x, &p.x + 3, vertices + 3 * g.index(x, y));
    }
  std::size_t t = 0;
  for (int y = 0; y + 1 < g.height; ++y)
    for (int x = 0; x + 1 < g.width; ++x) {
      auto a = static_cast<unsigned>(g.index(x, y)), b = static_cast<unsigned>(g.index(x + 1, y));
      auto c = static_cast<unsigned>(g.index(x, y + 1)),
           d = static_cast<unsigned>(g.index(x + 1, y + 1));
      unsigned tri[6] = {a, c, b, b, c, d};
      std::copy(tri, tri + 6, indices + 6 * t++);
    }
  rtcCommitGeometry(mesh);
  return mesh;
}

}  // namespace eco
