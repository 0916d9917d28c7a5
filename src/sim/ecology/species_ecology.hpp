// A species' niche and life history for the ecosystem simulation (docs/ecology.md): the
// `[ecology]` table of a species file.
// - The niche: tolerance curves map four living conditions (altitude through temperature,
//   slope, moisture, windiness) to a site suitability in [0, 1]. By default they are derived
//   from the species' Ellenberg indicator values (Ellenberg et al. 1991, the EcoMod paper's
//   ref. [16]) and its wind firmness, by the rules of docs/ecology.md; a file may replace any
//   of them with its own polyline. Light, the fifth condition, enters once: as the light
//   response to the light that reaches the plant through terrain and canopy.
// - The life history: growth, allometry, mortality and reproduction, with their sources in
//   the species files (iLand's European parameter set, Wiedemann's yield tables).
#pragma once

#include <array>
#include <filesystem>
#include <optional>

#include "core/polyline.hpp"
#include "sim/scenario.hpp"

namespace eco {

class TomlTable;

// Ellenberg indicator values; 0 stands for "x", indifferent.
struct Ellenberg {
  int light = 0;        // L, 1 (deep shade) .. 9 (full light)
  int temperature = 0;  // T, 1 (alpine) .. 9 (hottest lowlands)
  int moisture = 0;     // F, 1 (extremely dry) .. 12 (submerged)
};

// The living conditions of the EcoMod paper that make a site suitable, in the order of
// ToleranceCurves::of(). Sunniness is the paper's fifth: it acts through the light response.
enum class Condition { Altitude, Slope, Moisture, Windiness };
inline constexpr int kConditionCount = 4;
const char* toString(Condition condition);

struct ToleranceCurves {
  Polyline altitude_m;  // over altitude in metres (through the climate's temperature)
  Polyline slope_deg;   // over slope in degrees
  Polyline moisture;    // over the site's moisture number, Ellenberg's F scale (1 .. 12)
  Polyline windiness;   // over the windiness field, 0..1
  const Polyline& of(Condition c) const;
  Polyline& of(Condition c);
};

// The yearly step's powers, exponentials and logarithms (the height curve's year on, the
// allometries, the crown's width and leaves, the aging) are worked out in single precision,
// as the plants keep their numbers, at half the cost of double's: their results hold to this
// share of their value.
inline constexpr double kGrowthPrecision = 1e-6;

// Chapman-Richards growth: value(t) = max (1 - exp(-rate t))^shape.
class GrowthCurve {
 public:
  GrowthCurve() : GrowthCurve(1.0, 0.03, 1.3) {}
  GrowthCurve(double max, double rate_per_year, double shape);
  double max() const { return max_; }
  double at(double years) const;
  // The curve a year after it reached `value` (max at or above max): at(age + 1) where
  // at(age) = value, in closed form without the age, since exp(-rate (age + 1)) =
  // (1 - (value / max)^(1 / shape)) exp(-rate). Two pows, for every plant every year,
  // instead of a round trip through the age's three pows, two exps and a log.
  double yearAfter(double value) const;

 private:
  double max_, rate_, shape_;
  float inverseShape_, yearDecay_, yearGain_;  // 1 / shape, exp(-rate), 1 - exp(-rate): once
};

enum class DispersalVector { Gravity, Animal, Wind };

// A biomass allometry: kg = a dbh_cm^b (iLand's bm*_a, bm*_b).
struct Allometry {
  double a = 0.0, b = 0.0;
  double at(double dbh_cm) const;
};

// iLand's aging (Seidl et al. 2012, after Landsberg and Waring 1997): production falls as a
// tree nears its species' maximum height or age, 1 / (1 + (x / halfAt)^exponent) of it, x
// the harmonic mean of the two relative to their maxima (0 young and small .. 1 at either
// maximum). halfAt 0 is no aging.
struct Aging {
  double halfAt = 0.0;  // x at which production is halved
  double exponent = 2.0;
};

// The longest life and the most poor years in a row a species file may give: a plant keeps
// its age in 16 bits and its poor years in 8 (plants.hpp; a landscape holds 100 million).
inline constexpr int kLongestLife_years = 10000;
inline constexpr int kMostSaplingStressYears = 255;

struct LifeHistory {
  // Growth and form.
  int maxAge_years = 300;
  GrowthCurve height_m;      // potential (top) height over age on the best site, in full light
  double formFactor = 0.45;  // stem volume / (basal area x height)
  // Biomass of the tree's parts over its diameter: the foliage, and the wood that a year's
  // growth adds to (stem, branches, coarse roots).
  Allometry foliage{0.02, 1.7}, stem{0.2, 2.25}, branches{0.02, 2.3}, coarseRoots{0.02, 2.3};
  double specificLeafArea = 10.0;  // m2 of leaf per kg of foliage, of a crown in full light
  // Shade leaves: leaves grown in deep shade are thinner, at this share of the leaf mass per
  // area of sun leaves (linear in the light in between), so the same foliage mass spreads
  // into more leaf area down a shaded crown (docs/ecology.md, "Sun and shade leaves").
  double shadeLeafMassRatio = 1.0;
  // What keeping the crown costs each year: the share of the foliage renewed, and fine roots
  // in proportion to the foliage, with their own turnover.
  double leafTurnover = 1.0;           // a year, of the foliage
  double fineRootFoliageRatio = 0.75;  // fine root mass / foliage mass
  double fineRootTurnover = 1.0;       // a year, of the fine roots
  // Crown diameter of SILVA (Pretzsch et al. 2002): cd_m = exp(a0 + a1 ln dbh_cm + a2 h_m +
  // a3 ln(h_m / dbh_cm)).
  std::array<double, 4> crownDiameterSilva = {0.34, 0.33, 0.0145, -0.041};
  double crownRatio = 0.6;               // open-grown crown length / tree height
  double saplingHeightDiameter = 120.0;  // height / dbh of a sapling as it passes 1.3 m
  double maxHeightDiameter = 150.0;      // height / dbh a stem can carry at most
  // Production: biomass made from the light a tree absorbs (net of respiration).
  double lightUseEfficiency = 1.5;  // kg of dry matter per m2 of open-sky light absorbed, a year
  Aging aging;                      // how production falls with size and age (none by default)
  // Mortality.
  double intrinsicSurvival = 0.01;       // share of trees that would reach max age (iLand)
  double stressMortality = 1.4;          // yearly hazard at a full carbon deficit (iLand)
  int saplingStressYears = 3;            // saplings die after this many poor years in a row
  double saplingStressThreshold = 0.05;  // a poor year grows less than this share of potential
  // Reproduction.
  int maturityAge_years = 40;  // first year of seed production
  // Seeds per m2 of crown projection in a mast year. iLand's fecundity_m2 counts potential
  // seedlings, the seeds that survive to germinate (cf. Moles et al. 2004), so by default
  // none of them is lost again before the site, light and seedbed decide.
  double fecundity_m2 = 40.0;
  int mastIntervalYears = 1;     // mean years between mast years
  double nonMastFraction = 1.0;  // seed production in other years, share of a mast year's
  double germination = 1.0;  // seeds that become one-year seedlings on a free, suitable, lit spot
  // Establishment on litter and in a sward, relative to bare mineral soil (seedbed.hpp).
  double litterEstablishment = 1.0;
  double swardEstablishment = 1.0;
  double seedlingHeight_m = 0.15;  // height in the year a seed establishes
  DispersalVector dispersal = DispersalVector::Gravity;
  double dispersalMean_m = 15.0;  // mean distance of the seed kernel
  double downwindBias = 0.0;      // wind-dispersed: drift downwind per metre travelled
  // A two-part kernel (TreeMig, Lischke et al. 2006; iLand): this share of the seeds
  // travels with the long mean instead (jays caching nuts, updrafts lifting seeds).
  double longDistanceFraction = 0.0;
  double longDistanceMean_m = 0.0;
};

struct Ecology {
  Ellenberg ellenberg;
  double windFirmness = 150.0;  // critical turning moment coefficient CReg (iLand's wind table)
  // Curves the file gives itself; the others are derived for the scenario's climate.
  std::array<std::optional<Polyline>, kConditionCount> toleranceOverride;
  Polyline lightResponse;  // vigor allowed by light, over light as a fraction of open sky
  LifeHistory life;

  // The niche on a site of this climate: derived curves, or the file's own.
  ToleranceCurves tolerances(const Climate& climate) const;
  // Below this light (fraction of open sky) leaves do not pay their way: the crown's lowest
  // branches die there, and a sapling cannot grow (Ellenberg's L).
  double lightCompensation() const;
};

// The documented derivations (docs/ecology.md).
// Minimum relative light a plant of light value L lives with (Ellenberg's definitions of L).
double lightCompensation(int light);
Polyline lightResponseFor(int light);
// The mean annual temperature of Ellenberg's temperature value T (ours, from central
// Europe's vegetation belts), and the altitude with that temperature in a climate.
double meanAnnualTemperatureOf(double temperatureValue);
double altitudeOfTemperature(double temperature_c, const Climate& climate);
ToleranceCurves deriveTolerances(const Ellenberg& values, double windFirmness,
                                 const Climate& climate);

// Reads an [ecology] table; throws InputError at the file, line and key at fault.
Ecology parseEcology(TomlTable& table);
// The [ecology] table of a species file, or nothing when it has none.
std::optional<Ecology> readEcology(const std::filesystem::path& speciesFile);

}  // namespace eco
