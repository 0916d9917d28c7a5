// The one Embree device of the process, and the terrain mesh both Embree scenes (sunniness,
// canopy light) are built on. Embree reports errors through a callback; the device keeps
// the first message and check() turns it into an exception after the call that failed.
#pragma once

#include <functional>
#include <mutex>
#include <string>

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include "sim/terrain.hpp"

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

// The terrain as a committed triangle geometry: a vertex at every cell centre, placed by
// `position(x, y)`, and two triangles per grid square split along the diagonal from its
// north-east to its south-west corner (the surface Terrain::altitudeAt interpolates).
RTCGeometry newTerrainGeometry(const Terrain& terrain,
                               const std::function<glm::vec3(int x, int y)>& position);

}  // namespace eco
