// What foresters measure in a stand (docs/ecology.md, "Forester's measures"), from the
// plants' arrays: stems and basal area of the trees of at least 10 cm dbh, their quadratic
// mean diameter, Reineke's stand density index, their stem volume, and the dominant height.
#pragma once

#include <vector>

#include "sim/ecology/ecosystem.hpp"

namespace eco {

inline constexpr double kMeasuredDbh_m = 0.10;  // the calipering limit of the measures
inline constexpr double kReinekeSlope = 1.605;  // Reineke (1933): N ~ Dq^-1.605
inline constexpr double kReinekeReference_cm = 25.4;

struct StandMeasures {
  double stemsPerHa = 0.0;         // dbh >= 10 cm
  double basalArea_m2PerHa = 0.0;  // dbh >= 10 cm
  double qmd_cm = 0.0;             // quadratic mean diameter of those stems
  double sdi = 0.0;                // Reineke: stems x (qmd / 25.4 cm)^1.605
  double volume_m3PerHa = 0.0;     // their stem volume, form factor x basal area x height
  double dominantHeight_m = 0.0;   // mean height of the 100 tallest trees per hectare
  std::size_t plants = 0;          // every plant, seedlings too
  double meanHeight_m = 0.0;       // of every plant
};

// The sums the measures are made of: each tree of at least the calipering limit adds its
// stem, basal area and volume.
struct StandTally {
  double stems = 0.0, basalArea_m2 = 0.0, diameterSquares_m2 = 0.0, volume_m3 = 0.0;
  void add(double dbh_m, double height_m, double formFactor);  // thinner trees add nothing
  void add(const StandTally& other);                           // another part of the stand
  // The measures on `area_ha` (all but the dominant height).
  StandMeasures perHectare(double area_ha) const;
};

// The basal area of a stem, m2.
double basalAreaOf(double dbh_m);

// The measures on `area_ha` of each species' plants, in the species' order, and last of all
// the plants together: one pass over the plants in blocks side by side, each block's sums
// in plant order and the blocks' in order, so the figures do not depend on the thread count.
std::vector<StandMeasures> measureStands(const Plants& plants,
                                         const std::vector<EcosystemSpecies>& species,
                                         double area_ha);

// The basal area (trees of at least 10 cm) of the densest whole block of block_m x block_m
// on the map, per hectare; 0 where the map holds no whole block.
double densestBlockBasalArea(const Plants& plants, const Grid& grid, double block_m = 100.0);

}  // namespace eco
