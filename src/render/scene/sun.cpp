#include "render/scene/sun.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/exponential.hpp>

#include "core/frames.hpp"
#include "sim/conditions/sunlight.hpp"

namespace eco {

glm::vec3 sunWorldDirection(double latitude_deg, SunTime time) {
  return worldDirectionFromMap(
      sunDirection(latitude_deg, solarDeclination(time.dayOfYear), hourAngleOf(time.solarHour)));
}

Lighting lightingFor(double latitude_deg, SunTime time) {
  Lighting light;
  light.toSun = sunWorldDirection(latitude_deg, time);
  const float elevation = std::max(light.toSun.y, 0.0f);  // sine of the sun's height
  // Air mass grows toward the horizon; blue is scattered out of the beam first.
  const float airMass = 1.0f / (elevation + 0.15f);
  const glm::vec3 extinction(0.06f, 0.10f, 0.20f);
  light.sunColor = 2.6f * glm::exp(-extinction * airMass) * glm::smoothstep(0.0f, 0.08f, elevation);
  const float day = glm::smoothstep(-0.1f, 0.2f, light.toSun.y);
  light.skyZenith = glm::mix(glm::vec3(0.02f, 0.03f, 0.08f), glm::vec3(0.22f, 0.42f, 0.82f), day);
  light.skyHorizon = glm::mix(glm::vec3(0.05f, 0.05f, 0.10f), glm::vec3(0.68f, 0.78f, 0.90f), day);
  light.ambient = 0.3f * (light.skyZenith + light.skyHorizon);
  return light;
}

}  // namespace eco
