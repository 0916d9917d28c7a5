// The ground a seed falls on (docs/ecology.md, "Establishment"): the litter of a canopy that
// takes more than half the light, a sward of grasses and herbs where the light reaches the
// ground, or bare mineral soil where the sward is thin (dry ground, steep slopes). Small
// seeds take poorly on litter and in a sward (pine needs bare mineral soil); large ones
// (beech nuts, which jays and mice bury) push through both. The renderer draws the same
// sward (render/scene/ground_cover.hpp), so the grass in a picture is the grass that keeps
// a pine's seeds from the soil.
#pragma once

#include "sim/ecology/species_ecology.hpp"

namespace eco {

// Under a canopy that lets through less than this share of the sky's light the ground is
// covered in litter.
inline constexpr double kLitterLight = 0.5;

// The share of the ground that is soil rather than rock on a slope: 1 up to 40°, none from
// 50° (where the terrain shader shows rock).
float soilShareOnSlope(float slope_deg);

// The share of the ground a sward covers: `groundLight` the light reaching the ground
// relative to the sky's above the canopy (1 in the open), `moisture` on Ellenberg's F
// scale, `slope_deg` the terrain's.
float swardShare(float groundLight, float moisture, float slope_deg);

// The ground at a spot: litter, or the share of it a sward covers (the rest bare soil).
struct Seedbed {
  bool litter = false;
  double sward = 0.0;  // without litter
};
// The seedbed where `groundLight` reaches the ground (relative to the open), on ground of
// this moisture and slope: under litter the sward is not looked up.
Seedbed seedbedAt(double groundLight, float moisture, float slope_deg);

// How well a species' seeds take on this ground, relative to bare mineral soil: its litter
// establishment on litter; elsewhere bare soil where the sward leaves it and the species'
// sward establishment in the sward.
double seedbedEstablishment(const LifeHistory& life, const Seedbed& seedbed);

}  // namespace eco
