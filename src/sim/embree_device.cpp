#include "sim/embree_device.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "sim/terrain_mesh.hpp"

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

RTCGeometry newTerrainGeometry(const Terrain& terrain) {
  const Grid& g = terrain.grid;
  EmbreeDevice& device = embree();
  const std::vector<std::uint32_t> triangles = terrainTriangles(g);
  RTCGeometry mesh = rtcNewGeometry(device.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<glm::vec3*>(rtcSetNewGeometryBuffer(
      mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(glm::vec3), g.cellCount()));
  auto* indices = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(std::uint32_t), triangles.size() / 3));
  device.check("allocating the terrain mesh");
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) vertices[g.index(x, y)] = cellPosition(terrain, x, y);
  std::copy(triangles.begin(), triangles.end(), indices);
  rtcCommitGeometry(mesh);
  return mesh;
}

}  // namespace eco
