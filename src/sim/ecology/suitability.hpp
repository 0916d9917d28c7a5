// How well a site suits a species (docs/ecology.md): each living condition through the
// species' tolerance curve gives a suitability in [0, 1] (sunniness acts through the light
// response instead, with the canopy's shade: light counts once); the site's suitability is their
// minimum (Liebig's law of the minimum, as the EcoMod paper puts it: "a single inconvenient
// living condition can fully stop the prosperity of some tree") or, as an option, product.
#pragma once

#include <array>

#include "sim/conditions/conditions.hpp"
#include "sim/ecology/species_ecology.hpp"

namespace eco {

std::array<double, kConditionCount> conditionSuitabilities(const ToleranceCurves& tolerance,
                                                           const ConditionFields& fields,
                                                           std::size_t cell);
double combineSuitabilities(const std::array<double, kConditionCount>& values,
                            SuitabilityRule rule);

// The site suitability of every cell for one species.
Field siteSuitability(const ToleranceCurves& tolerance, const ConditionFields& fields,
                      SuitabilityRule rule);

}  // namespace eco
