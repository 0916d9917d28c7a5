// One year of a plant's life (docs/ecology.md, "Growth" and "Mortality"), as pure
// functions of its state and what its site and the canopy give it.
// - A sapling (a young plant of iLand's sapling layer, below 4 m: ecosystem.hpp) grows in
//   height only: the species' potential height increment, scaled by the site's suitability
//   and its light response. From breast height on its diameter is the sapling
//   height/diameter ratio's.
// - A tree makes biomass from the light its crown absorbs (a light-use efficiency). It first
//   renews its leaves and fine roots (their turnover: iLand's allocation, Seidl et al. 2012);
//   what is left adds wood to stem, branches and coarse roots by their allometries, which
//   sets the new diameter. Its height grows by the potential increment scaled by suitability
//   and the light at its top, but no more slender than the species can carry: a suppressed
//   tree keeps growing in height on little wood. A tree whose production does not cover its
//   upkeep starves. As a leaf pays its way only above a light (leafCompensationLight()), a
//   stand's leaf area is bounded, and the number of trees falls as their foliage grows:
//   self-thinning along the foliage allometry.
#pragma once

#include "sim/ecology/species_ecology.hpp"

namespace eco {

// Plants shorter than this have no stem diameter.
inline constexpr double kBreastHeight_m = 1.3;

// Stem volume: form factor x basal area x height, m3.
double stemVolume(const LifeHistory& life, double dbh_m, double height_m);
// Crown radius from stem diameter and height (SILVA's crown diameter function), at most half
// the height.
double crownRadiusOf(const LifeHistory& life, double dbh_m, double height_m);
// Below breast height SILVA's function is held at its value for 1 cm and 1.3 m, so a
// seedling's crown radius is min(this, half its height): crownRadiusOf's, without its
// exp and two logs for each of millions of seedlings a year.
double seedlingCrownRadiusLimit(const LifeHistory& life);
// A crown's foliage: its mass (iLand's foliage allometry) and the leaf area it spreads into.
// Leaves are built in the light they get (sun and shade leaves): from the crown's top down,
// as the light falls by Beer's law, each layer's leaf mass per area falls from the sun
// leaves' (1 / specific leaf area) to shadeLeafMassRatio of it in darkness, linear in the
// light, so the same mass spreads into more leaf area the deeper the crown and the darker
// its top (docs/ecology.md, "Sun and shade leaves"). No crown holds more than its
// projection can light: leaves deeper than where the open sky's light has fallen to the leaf
// compensation light never pay their way, so a crown holds at most maxCrownLeafAreaIndex()
// m2 of leaf per m2 of projection, and only the mass of those leaves. Pruning moves the
// leaves up the stem, to where there is light, but does not shrink them: a suppressed tree
// must feed all of them.
struct CrownFoliage {
  double leafArea_m2 = 0.0;
  double foliage_kg = 0.0;
};
// `topLight` is the light at the crown's top relative to the open (last year's).
CrownFoliage crownFoliage(const LifeHistory& life, double dbh_m, double height_m, double topLight);
double maxCrownLeafAreaIndex(const LifeHistory& life);
// The deepest crown's leaf area index and the share of light its leaves absorb, 1 - exp(-k L):
// a species' constants, which the yearly step works out once instead of a log and an expm1
// for each crown each year.
struct FoliageLimit {
  double leafAreaIndex = 0.0;
  double absorbedShare = 0.0;
};
FoliageLimit foliageLimitOf(const LifeHistory& life);
// The yearly step's form: with the species' limit worked out once, and the crown's radius as
// the light model spreads its leaves (crownRadiusOf's, kept from last year's growth).
CrownFoliage crownFoliage(const LifeHistory& life, const FoliageLimit& limit, double dbh_m,
                          double crownRadius_m, double topLight);
// Wood (stem, branches, coarse roots), kg, and its inverse.
double woodyBiomass(const LifeHistory& life, double dbh_m);
// The inverse starts from `guess_m` when given (the diameter before a year's growth).
double diameterOfWoodyBiomass(const LifeHistory& life, double biomass_kg, double guess_m = 0.0);
// The leaf mass per area of leaves grown in this light (relative to the open), as a share
// of the sun leaves': from the species' shade ratio in darkness to 1 in full light.
double leafMassShare(const LifeHistory& life, double light);
// The yearly upkeep of a crown's leaves and the fine roots that feed them (in proportion to
// the foliage's mass), kg.
double crownUpkeep(const LifeHistory& life, double foliage_kg);
// The light (fraction of open sky) at which a leaf acclimated to it makes just its upkeep:
// branches in less light die (crown pruning).
double leafCompensationLight(const LifeHistory& life);
// The potential height increment over one year from a height (the curve's next year from the
// age it has that height).
double potentialHeightIncrement(const LifeHistory& life, double height_m);

// iLand's aging factor of a tree this tall and old (LifeHistory::aging), 0..1.
double agingFactor(const LifeHistory& life, double height_m, int age_years);

// What a plant's place and nature give its growth this year.
struct GrowingConditions {
  double suitability = 1.0;    // the site's, 0..1
  double lightResponse = 1.0;  // the species' response to the light at the plant's top, 0..1
  double growthFactor = 1.0;   // the individual's lasting rate (genotype, microsite), at most 1
  double aging = 1.0;          // a tree's agingFactor(); the height curve has its own
  // Share of the potential height increment: site, light and individual.
  double heightShare() const;
  // Share of the light-use efficiency: site, individual and aging (light enters as absorbed
  // light).
  double productionShare() const;
};

struct TreeYear {
  double dbh_m = 0.0;
  double height_m = 0.0;
  double production_kg = 0.0;  // light-use efficiency x absorbed light x production share
  double upkeep_kg = 0.0;      // what the leaves and fine roots cost this year
  // The share of the upkeep production did not cover, 0 (none missing) .. 1 (nothing made).
  double carbonDeficit() const;
};

// A tree's growth over a year. `absorbed_m2` is the light its crown (of `foliage_kg`)
// absorbed, in m2 of open-sky light.
TreeYear growTree(const LifeHistory& life, double dbh_m, double height_m, double foliage_kg,
                  double absorbed_m2, const GrowingConditions& conditions);

// A sapling's new height, and whether the year was poor for it (less than the species'
// stress threshold of its potential growth).
struct SaplingYear {
  double height_m = 0.0;
  bool poor = false;
};
SaplingYear growSapling(const LifeHistory& life, double height_m,
                        const GrowingConditions& conditions);
// The stem diameter of a sapling this tall (at least breast height), and of a tree as it
// leaves the sapling layer.
double saplingDiameter(const LifeHistory& life, double height_m);

// Probability that a tree dies this year: the intrinsic rate that lets `intrinsicSurvival` of
// a cohort reach the maximum age, certain at it, plus iLand's carbon-starvation hazard
// 1 - exp(-stressMortality x deficit) (Seidl et al. 2012).
double treeMortality(const LifeHistory& life, int age_years, double carbonDeficit);
// The intrinsic part alone, a year.
double intrinsicMortality(const LifeHistory& life);
// The carbon-starvation part alone.
double starvationMortality(const LifeHistory& life, double carbonDeficit);

// Seeds a mature tree sends out this year: fecundity per m2 of crown projection, in full in
// a mast year and the non-mast share otherwise, scaled by how much of its crown's potential
// light the tree gets (a suppressed tree hardly fruits).
double seedProduction(const LifeHistory& life, double crownRadius_m, bool mastYear,
                      double relativeLight);
// Seeds per m2 of crown projection in the light, in a mast year or another.
double seedsPerCrownArea(const LifeHistory& life, bool mastYear);

}  // namespace eco
