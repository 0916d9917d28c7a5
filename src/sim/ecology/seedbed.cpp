#include "sim/ecology/seedbed.hpp"

#include <algorithm>

#include <glm/common.hpp>

namespace eco {

float soilShareOnSlope(float slope_deg) {
  return glm::smoothstep(50.0f, 40.0f, slope_deg);
}

float swardShare(float groundLight, float moisture, float slope_deg) {
  // Meadow grasses need light (Ellenberg L 7-8): a closing canopy shades them out, and a
  // tenth of even open ground stays bare (molehills, tracks, the gaps between tussocks). On
  // dry ground (F 3 and less) they thin to a sparse dry grassland. Ours, read from
  // Ellenberg's values of the meadow grasses.
  return 0.9f * glm::smoothstep(0.4f, 0.9f, std::clamp(groundLight, 0.0f, 1.0f)) *
         glm::smoothstep(2.0f, 4.0f, moisture) * soilShareOnSlope(slope_deg);
}

Seedbed seedbedAt(double groundLight, float moisture, float slope_deg) {
  if (groundLight < kLitterLight) return {true, 0.0};
  return {false, swardShare(static_cast<float>(groundLight), moisture, slope_deg)};
}

double seedbedEstablishment(const LifeHistory& life, const Seedbed& seedbed) {
  if (seedbed.litter) return life.litterEstablishment;
  const double s = std::clamp(seedbed.sward, 0.0, 1.0);
  return 1.0 - s * (1.0 - life.swardEstablishment);
}

}  // namespace eco
