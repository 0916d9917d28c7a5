// The light of a frame: the sun's direction from the scenario's latitude and a chosen day and
// solar time (the same solar geometry as the sunniness condition), its colour and the sky's
// colours.
#pragma once

#include <glm/vec3.hpp>

namespace eco {

struct SunTime {
  double dayOfYear = 172.0;  // 21 June
  double solarHour = 10.0;   // 12 = solar noon
};

struct Lighting {
  glm::vec3 toSun{0.0f, 1.0f, 0.0f};  // world frame (x east, y up, z south), unit
  glm::vec3 sunColor{1.0f};           // linear RGB irradiance of the beam
  glm::vec3 skyZenith{0.25f, 0.45f, 0.85f};
  glm::vec3 skyHorizon{0.70f, 0.80f, 0.92f};
  glm::vec3 ambient{0.3f};  // linear RGB from the sky hemisphere
};

// Direction toward the sun in the world frame; below the horizon when y < 0.
glm::vec3 sunWorldDirection(double latitude_deg, SunTime time);

// Light of a clear day with the sun at that direction; the sun dims and reddens toward the
// horizon, and only the sky lights the scene once the sun has set.
Lighting lightingFor(double latitude_deg, SunTime time);

}  // namespace eco
