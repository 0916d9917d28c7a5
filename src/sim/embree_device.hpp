// The one Embree device of the process, and the terrain mesh both Embree scenes (sunniness,
// canopy light) are built on. Embree reports errors through a callback; the device keeps
// the first message and check() turns it into an exception after the call that failed.
#pragma once

#include <mutex>
#include <string>

#include <embree3/rtcore.h>

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

// The terrain's triangles (terrain_mesh.hpp) in the map frame as a committed triangle
// geometry.
RTCGeometry newTerrainGeometry(const Terrain& terrain);

}  // namespace eco
