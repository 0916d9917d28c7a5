// One year of a plant's life history (docs/ecology.md, "Growth" and "Mortality"): growth
// along the species' Chapman-Richards curves at the pace its vigor allows, crown size from
// allometry, and the yearly chance of dying.
#pragma once

#include "sim/ecology/species_ecology.hpp"

namespace eco {

// Plants shorter than this have no stem diameter and cast no shade in the light model.
inline constexpr double kBreastHeight_m = 1.3;

// Grows `value` by vigor times the curve's increment over one year from the age at which
// the curve reaches `value`: a plant at full vigor follows the curve, a suppressed one
// stalls, and nothing exceeds the curve's maximum.
double grownValue(const GrowthCurve& curve, double value, double vigor);

// Crown radius from the stem diameter (the species' allometry), at most half the height so
// that small plants are not wider than tall.
double crownRadiusOf(const LifeHistory& life, double dbh_m, double height_m);

// Seeds a mature plant sends out this year: the species' seeds_per_year at 30 cm stem
// diameter, scaled by (dbh / 30 cm)^2 as SORTIE's fecundity (Ribbens, Silander and Pacala
// 1994) and by vigor. Shrubs, whose stems stay thin, use their maximum diameter as reference.
double seedCount(const LifeHistory& life, double dbh_m, double vigor);

// Probability of dying this year: the intrinsic rate 4.605 / max age of JABOWA (Botkin et
// al. 1972: 1 % of trees reach the maximum age), certain death past the maximum age, and
// 0.368 a year once vigor has stayed below the stress threshold too many years in a row.
double mortalityProbability(const LifeHistory& life, int age_years, int stressYears);

}  // namespace eco
