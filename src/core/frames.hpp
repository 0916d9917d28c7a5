// The frames of ecoforest, each named once (as pbrt names renderFromObject):
// - map:   east, north, altitude in metres — the simulation's frame (plants, CSVs, Embree
//          scenes). East is measured from the westmost cell centres and north from the
//          southmost (sim/grid.hpp); grid rows count from the north edge.
// - world: x east, y up, z south in metres — the tree model's frame, the renderer's and
//          glTF's right-handed y-up convention.
// - bearing: a compass direction in degrees, clockwise from north (0 north, 90 east), as
//          wind and aspect are given.
#pragma once

#include <cmath>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/angles.hpp"

namespace eco {

// A map position (east, north, altitude) in the world frame.
inline glm::vec3 worldFromMap(double east_m, double north_m, double altitude_m) {
  return {static_cast<float>(east_m), static_cast<float>(altitude_m), static_cast<float>(-north_m)};
}

inline glm::vec3 worldFromMap(glm::vec3 map) {
  return worldFromMap(map.x, map.y, map.z);
}

// The map position (east, north, altitude) of a world point.
inline glm::dvec3 mapFromWorld(glm::vec3 world) {
  return {world.x, -static_cast<double>(world.z), world.y};
}

// A direction given as (east, north, up) in the world frame.
inline glm::vec3 worldDirectionFromMap(glm::dvec3 enu) {
  return {static_cast<float>(enu.x), static_cast<float>(enu.z), static_cast<float>(-enu.y)};
}

// The horizontal unit vector (east, north) toward a compass bearing.
inline glm::dvec2 mapDirectionOfBearing(double bearing_deg) {
  const double angle = radians(bearing_deg);
  return {std::sin(angle), std::cos(angle)};
}

// The same in the world frame (y = 0).
inline glm::dvec3 worldDirectionOfBearing(double bearing_deg) {
  const glm::dvec2 d = mapDirectionOfBearing(bearing_deg);
  return {d.x, 0.0, -d.y};
}

// Winds are named by the bearing they come from; these are the directions they blow toward.
inline glm::dvec2 mapDownwindOf(double windFrom_deg) {
  return mapDirectionOfBearing(windFrom_deg + 180.0);
}
inline glm::dvec3 worldDownwindOf(double windFrom_deg) {
  return worldDirectionOfBearing(windFrom_deg + 180.0);
}

// The bearing a world direction points to (its horizontal part), degrees in (-180, 180].
inline float bearingOfWorldDirection(glm::vec3 direction) {
  return degrees(std::atan2(direction.x, -direction.z));
}

}  // namespace eco
