// Light in the forest (docs/ecology.md, "Light"): Embree rays from a point toward a set of
// weighted sky and sun directions, against the terrain and the crowns of the plants. Crowns
// are ellipsoids that pass light by Beer's law, so a ray through a crown keeps
// T^(chord / crown length) of its light, T being the species' vertical crown transmittance.
// Positions are map coordinates (Grid::cellAt): x east, y north, z altitude.
#pragma once

#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/conditions/sunlight.hpp"
#include "sim/terrain.hpp"

namespace eco {

// Directions over the sky hemisphere with the share of a year's light on a horizontal
// surface that each one brings: diffuse light evenly (the directions are spread by the
// cosine of the zenith angle), the sun's direct beam (SunPath) given to the nearest
// direction. Weights sum to 1. Rays look 150 m far: farther terrain is in the sunniness
// field, and crowns farther away are rarely in a ray's way.
struct LightDirections {
  std::vector<glm::dvec3> direction;
  std::vector<double> weight;
};
LightDirections makeLightDirections(double latitude_deg, int count,
                                    double diffuseFraction = SunlightSettings{}.diffuseFraction);

struct Crown {
  glm::vec3 centre;                   // map coordinates, metres
  float radius_m = 1.0f;              // horizontal semi-axis
  float halfLength_m = 1.0f;          // vertical semi-axis
  float opticalDepthPerMetre = 0.0f;  // -ln(T) / crown length
  int owner = -1;                     // the plant (row) this crown belongs to
};

// A point whose light is wanted, and the plant whose own crown does not shade it (-1: none).
struct LightProbe {
  glm::vec3 point;
  int self = -1;
};

class CanopyScene {
 public:
  explicit CanopyScene(const Terrain& terrain);
  ~CanopyScene();
  CanopyScene(const CanopyScene&) = delete;
  CanopyScene& operator=(const CanopyScene&) = delete;

  // Replaces the crowns (once a year, as plants grow, die and are born).
  void setCrowns(std::vector<Crown> crowns);
  const std::vector<Crown>& crowns() const { return crowns_; }

  // The light reaching each probe as a fraction of open-sky light on a horizontal surface,
  // in the probes' order. Runs in parallel; the probes are traced in small packets of
  // nearby points, and each result is the same as lightAt's for that probe alone.
  std::vector<float> lightAt(const std::vector<LightProbe>& probes,
                             const LightDirections& sky) const;
  double lightAt(glm::vec3 point, int self, const LightDirections& sky) const;

 private:
  struct Impl;
  void tracePacket(const LightProbe* const* probes, int count, const LightDirections& sky,
                   float* light) const;

  std::unique_ptr<Impl> impl_;
  std::vector<Crown> crowns_;
  float maxTerrain_m_ = 0.0f;
  float maxCrownTop_m_ = 0.0f;
};

}  // namespace eco
