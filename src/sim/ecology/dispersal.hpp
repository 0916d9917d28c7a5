// Where seeds land (docs/ecology.md, "Reproduction"): an exponential kernel in distance with
// the species' mean, in a uniformly random direction; wind-dispersed seeds also drift
// downwind by downwind_bias metres per metre travelled.
#pragma once

#include <glm/vec2.hpp>

#include "core/random.hpp"
#include "sim/ecology/species_ecology.hpp"

namespace eco {

// The map offset (east, north) of one seed from its parent. `downwind` is the unit vector
// toward which the prevailing wind blows.
glm::dvec2 seedOffset(const LifeHistory& life, glm::dvec2 downwind, Rng& rng);

}  // namespace eco
