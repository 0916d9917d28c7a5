// What a tree's form answers to on its site (docs/ecology.md, "A tree's site, for its
// form"), for the tree model's shaping (model/tree_shaping.hpp). Worked out for the plants
// of a snapshot, not kept per plant: it costs eight light samples a tree, and a landscape
// has fifty million plants.
//   light: where the light comes from and how one-sided it is -- the light-weighted mean of
//          eight horizontal directions, the light sampled around the crown at mid-crown
//          height just beyond its own footprint. Even light all round gives 0; a forest edge
//          (light from one half) about 0.65; light from one direction only 1.
//   wind:  the prevailing wind's direction times the site's exposure, the windiness above
//          open level ground's rescaled to 0..1: open level ground and lees are 0, the most
//          exposed ridges 1.
//   crowding: the crown base the simulation keeps per plant (self-pruning, ecosystem.hpp).
#pragma once

#include <vector>

#include <glm/vec2.hpp>

#include "sim/ecology/light_grid.hpp"
#include "sim/ecology/plants.hpp"
#include "sim/grid.hpp"

namespace eco {

// Below breast height a plant's form is not shaped (it is drawn a few pixels tall).
inline constexpr double kShapedFromHeight_m = 1.3;

struct PlantSite {
  glm::vec2 light{0.0f};  // toward the light (east, north), length 0..1: one-sidedness
  glm::vec2 wind{0.0f};   // toward where the wind blows (east, north), length 0..1: exposure
};

// The light direction at a crown from this year's light grid.
glm::dvec2 lightDirection(const LightGrid& light, double east_m, double north_m,
                          double crownRadius_m, double crownBase_m, double height_m);

// A site's exposure, 0..1, from its windiness (conditions/windiness.hpp).
double windExposure(double windiness);

// Plant i's site; `windiness` is the conditions' field on `grid`, `downwind` the prevailing
// wind's direction (mapDownwindOf, worked out once by the caller), and the light grid must
// have been computed this year (after a step).
PlantSite plantSite(const Plants& plants, std::size_t i, const LightGrid& light, const Grid& grid,
                    const Field& windiness, glm::dvec2 downwind);
// Each plant's site, likewise, with the wind blowing from `windFrom_deg`.
std::vector<PlantSite> plantSites(const Plants& plants, const LightGrid& light, const Grid& grid,
                                  const Field& windiness, double windFrom_deg);

}  // namespace eco
