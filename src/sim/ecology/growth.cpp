#include "sim/ecology/growth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/ecology/light_grid.hpp"

namespace eco {
namespace {

constexpr double kQuarterPi = std::numbers::pi / 4.0;

// A step of Halley's method for f(x) = 0 from f, f' and f'': Newton's step f / f' divided by
// 1 - f f'' / (2 f'^2), which makes the convergence cubic; as one division, 2 f f' / (2 f'^2
// - f f''), the steps' chain waiting on one division instead of three. Far from the root,
// where that divisor is below a half, it is Newton's step.
double halleyStep(double f, double slope, double curvature) {
  const double slope2 = slope * slope;
  const double denominator = 2.0 * slope2 - f * curvature;
  return denominator > slope2 ? 2.0 * f * slope / denominator : f / slope;
}

// Halley's iterations stop once a step is below this share of the value: the next step, the
// error left, is near its cube (1e-12), far below a float's resolution (6e-8).
constexpr double kHalleyTolerance = 1e-4;

// SILVA's crown diameter; fitted to trees of measurable diameter, so below 1 cm (and a
// sapling's breast height) it is held at its value there.
double silvaCrownDiameter(const LifeHistory& life, double dbh_m, double height_m) {
  const auto dbh_cm = static_cast<float>(std::max(1.0, 100.0 * dbh_m));
  const auto h = static_cast<float>(std::max(kBreastHeight_m, height_m));
  const auto& a = life.crownDiameterSilva;
  // In single precision (kGrowthPrecision): every tree, every year.
  return std::exp(
      static_cast<float>(a[0] + a[1] * std::log(dbh_cm) + a[2] * h + a[3] * std::log(h / dbh_cm)));
}

}  // namespace

double stemVolume(const LifeHistory& life, double dbh_m, double height_m) {
  return life.formFactor * kQuarterPi * dbh_m * dbh_m * height_m;
}

double crownRadiusOf(const LifeHistory& life, double dbh_m, double height_m) {
  // Small plants' crowns are only bounded by their height.
  return std::min(0.5 * silvaCrownDiameter(life, dbh_m, height_m), 0.5 * height_m);
}

double seedlingCrownRadiusLimit(const LifeHistory& life) {
  return 0.5 * silvaCrownDiameter(life, 0.0, 0.0);
}

double maxCrownLeafAreaIndex(const LifeHistory& life) {
  // Beer's law: under a leaf area index L the light is exp(-k L) of the crown top's.
  return std::log(1.0 / std::min(1.0, leafCompensationLight(life))) / kLeafExtinction;
}

FoliageLimit foliageLimitOf(const LifeHistory& life) {
  const double lai = maxCrownLeafAreaIndex(life);
  return {lai, -std::expm1(-kLeafExtinction * lai)};
}

CrownFoliage crownFoliage(const LifeHistory& life, double dbh_m, double height_m, double topLight) {
  return crownFoliage(life, foliageLimitOf(life), dbh_m, crownRadiusOf(life, dbh_m, height_m),
                      topLight);
}

CrownFoliage crownFoliage(const LifeHistory& life, const FoliageLimit& limit, double dbh_m,
                          double crownRadius_m, double topLight) {
  const double area = std::numbers::pi * crownRadius_m * crownRadius_m;
  if (area <= 0.0) return {0.0, 0.0};
  const double sunMass = 1.0 / life.specificLeafArea;  // kg per m2 of sun leaves
  const double r = life.shadeLeafMassRatio;
  const double top = std::clamp(topLight, 0.0, 1.0);
  // Foliage mass per m2 of projection down to a leaf area index L, whose leaves absorb
  // 1 - exp(-k L) of the light: m(L) = sunMass (r L + (1 - r) top (1 - exp(-k L)) / k),
  // increasing and concave.
  auto massTo = [&](double lai, double absorbedShare) {
    return sunMass * (r * lai + (1.0 - r) * top * absorbedShare / kLeafExtinction);
  };
  const double maxLai = limit.leafAreaIndex;
  const double maxMass = massTo(maxLai, limit.absorbedShare);
  const double allometric_kg = life.foliage.at(100.0 * dbh_m);
  const double mass = allometric_kg / area;
  if (mass >= maxMass) return {maxLai * area, maxMass * area};
  // Halley's method from the sun leaves' area (below the root): m' is the mass per m2 of
  // leaf of the layer at depth L and m'' = -k (1 - r) top exp(-k L) sunMass its change,
  // both from the one exponential. Each step cubes the relative error, so a step below 1e-4
  // of L leaves an error near 1e-12, far below a float's resolution.
  double lai = mass / sunMass;
  for (int i = 0; i < 50; ++i) {
    // In single precision (kGrowthPrecision): every tree, every year.
    const double absorbedShare = 1.0 - std::exp(static_cast<float>(-kLeafExtinction * lai));
    const double transmitted = 1.0 - absorbedShare;
    const double excess = massTo(lai, absorbedShare) - mass;
    const double slope = sunMass * leafMassShare(life, top * transmitted);
    const double curvature = -sunMass * kLeafExtinction * (1.0 - r) * top * transmitted;
    const double step = halleyStep(excess, slope, curvature);
    lai -= step;
    if (std::abs(step) <= kHalleyTolerance * lai) break;
  }
  return {std::min(lai, maxLai) * area, allometric_kg};
}

namespace {

// The wood at a diameter (cm) and its first two derivatives. The three compartments' power
// laws share the diameter's logarithm: one log and three exps instead of three pows, which
// matters in the yearly step's hottest call (each tree, each year, two or three times).
struct WoodyAt {
  double biomass_kg = 0.0, slope_kg_per_cm = 0.0, curvature_kg_per_cm2 = 0.0;
};

WoodyAt woodyAt(const LifeHistory& life, double d_cm) {
  if (d_cm <= 0.0) return {};
  // The powers in single precision (kGrowthPrecision): Halley's steps need the sums and
  // slopes to far less than their 1e-4 (each tree, each year, two or three times).
  const float lnD = std::log(static_cast<float>(d_cm));
  auto power = [lnD](const Allometry& a) { return a.a * std::exp(static_cast<float>(a.b) * lnD); };
  const double stem = power(life.stem);
  const double branches = power(life.branches);
  const double roots = power(life.coarseRoots);
  auto curvature = [](double b, double term) { return b * (b - 1.0) * term; };
  return {stem + branches + roots,
          (life.stem.b * stem + life.branches.b * branches + life.coarseRoots.b * roots) / d_cm,
          (curvature(life.stem.b, stem) + curvature(life.branches.b, branches) +
           curvature(life.coarseRoots.b, roots)) /
              (d_cm * d_cm)};
}

// Halley's method on the increasing sum of power laws, from d_cm where the wood is `at`:
// from a tree's last diameter a year's growth takes two steps, or three in a young tree's
// fast years (2.8 evaluations of the wood a tree-year over the valley's first 30 years).
double halleyDiameter_m(const LifeHistory& life, double biomass_kg, double d_cm, WoodyAt at) {
  for (int i = 0; i < 30; ++i) {
    const double step =
        halleyStep(at.biomass_kg - biomass_kg, at.slope_kg_per_cm, at.curvature_kg_per_cm2);
    const double next = std::max(0.5 * d_cm, d_cm - step);
    if (std::abs(next - d_cm) < kHalleyTolerance * d_cm) return next / 100.0;
    d_cm = next;
    at = woodyAt(life, d_cm);
  }
  return d_cm / 100.0;
}

// The diameter after a year adds wood_kg to a tree of dbh_m: Halley's method from the
// evaluation that measured the tree's wood (none without a diameter).
double diameterAddingWood(const LifeHistory& life, double dbh_m, double wood_kg) {
  if (dbh_m <= 0.0) return diameterOfWoodyBiomass(life, wood_kg, 0.0);
  const WoodyAt now = woodyAt(life, 100.0 * dbh_m);
  return halleyDiameter_m(life, now.biomass_kg + wood_kg, 100.0 * dbh_m, now);
}

}  // namespace

double woodyBiomass(const LifeHistory& life, double dbh_m) {
  return woodyAt(life, 100.0 * dbh_m).biomass_kg;
}

double diameterOfWoodyBiomass(const LifeHistory& life, double biomass_kg, double guess_m) {
  if (biomass_kg <= 0.0) return 0.0;
  // From the guess, or from the stem's own inverse.
  const double d_cm =
      guess_m > 0.0 ? 100.0 * guess_m
                    : std::pow(biomass_kg / (life.stem.a + life.branches.a + life.coarseRoots.a),
                               1.0 / life.stem.b);
  return halleyDiameter_m(life, biomass_kg, d_cm, woodyAt(life, d_cm));
}

double leafMassShare(const LifeHistory& life, double light) {
  const double r = life.shadeLeafMassRatio;
  return r + (1.0 - r) * std::clamp(light, 0.0, 1.0);
}

double crownUpkeep(const LifeHistory& life, double foliage_kg) {
  return foliage_kg * (life.leafTurnover + life.fineRootFoliageRatio * life.fineRootTurnover);
}

double leafCompensationLight(const LifeHistory& life) {
  // A thin layer of leaves in light I absorbs k I per m2 of leaf (Beer's law's slope) and
  // costs U (r + (1 - r) I), U the upkeep of a m2 of sun leaves: they balance at
  // I = u r / (1 - u (1 - r)), u = U / (efficiency k) the balance of sun leaves.
  const double u =
      crownUpkeep(life, 1.0 / life.specificLeafArea) / (life.lightUseEfficiency * kLeafExtinction);
  if (u >= 1.0) return u;  // not even sun leaves in full light pay their way
  const double r = life.shadeLeafMassRatio;
  return u * r / (1.0 - u * (1.0 - r));
}

double potentialHeightIncrement(const LifeHistory& life, double height_m) {
  return std::max(0.0, life.height_m.yearAfter(height_m) - height_m);
}

double agingFactor(const LifeHistory& life, double height_m, int age_years) {
  if (life.aging.halfAt <= 0.0) return 1.0;
  // iLand's Species::aging: relative height and age, each kept below 1, combined as the
  // harmonic mean of their distances from the maxima.
  constexpr double kBelowOne = 0.999999;
  const double height = std::clamp(height_m / life.height_m.max(), 0.0, kBelowOne);
  const double age = std::clamp(static_cast<double>(age_years) / life.maxAge_years, 0.0, kBelowOne);
  const double x = 1.0 - 2.0 / (1.0 / (1.0 - height) + 1.0 / (1.0 - age));
  return 1.0 / (1.0 + std::pow(static_cast<float>(x / life.aging.halfAt),
                               static_cast<float>(life.aging.exponent)));
}

namespace {

double siteShare(const GrowingConditions& c) {
  return std::clamp(c.suitability, 0.0, 1.0) * std::max(0.0, c.growthFactor);
}

}  // namespace

double GrowingConditions::heightShare() const {
  return siteShare(*this) * std::clamp(lightResponse, 0.0, 1.0);
}

double GrowingConditions::productionShare() const {
  return siteShare(*this) * std::clamp(aging, 0.0, 1.0);
}

double TreeYear::carbonDeficit() const {
  if (upkeep_kg <= 0.0 || production_kg >= upkeep_kg) return 0.0;
  return std::min(1.0, (upkeep_kg - production_kg) / upkeep_kg);
}

TreeYear growTree(const LifeHistory& life, double dbh_m, double height_m, double foliage_kg,
                  double absorbed_m2, const GrowingConditions& conditions) {
  TreeYear year;
  year.production_kg = life.lightUseEfficiency * absorbed_m2 * conditions.productionShare();
  year.upkeep_kg = crownUpkeep(life, foliage_kg);
  const double wood_kg = year.production_kg - year.upkeep_kg;
  year.dbh_m = dbh_m;
  year.height_m = height_m;
  if (wood_kg <= 0.0) return year;  // nothing left to grow on
  year.dbh_m = std::max(dbh_m, diameterAddingWood(life, dbh_m, wood_kg));
  // Height as the light and the site allow, never past the species' maximum; and a metre
  // of height needs new wood: at most maxHeightDiameter metres per metre of new diameter,
  // so a tree that makes little wood falls behind its neighbours.
  const double increment =
      std::min(potentialHeightIncrement(life, height_m) * conditions.heightShare(),
               life.maxHeightDiameter * (year.dbh_m - dbh_m));
  year.height_m = std::min(life.height_m.max(), height_m + increment);
  return year;
}

SaplingYear growSapling(const LifeHistory& life, double height_m,
                        const GrowingConditions& conditions) {
  const double share = conditions.heightShare();
  return {
      std::min(life.height_m.max(), height_m + potentialHeightIncrement(life, height_m) * share),
      share < life.saplingStressThreshold};
}

double saplingDiameter(const LifeHistory& life, double height_m) {
  return height_m / life.saplingHeightDiameter;
}

double intrinsicMortality(const LifeHistory& life) {
  return 1.0 - std::pow(life.intrinsicSurvival, 1.0 / life.maxAge_years);
}

double treeMortality(const LifeHistory& life, int age_years, double carbonDeficit) {
  if (age_years >= life.maxAge_years) return 1.0;
  return std::min(1.0, intrinsicMortality(life) + starvationMortality(life, carbonDeficit));
}

double starvationMortality(const LifeHistory& life, double carbonDeficit) {
  // Without a deficit the hazard is 1 - exp(0) = 0: most trees skip the exponential.
  if (carbonDeficit <= 0.0) return 0.0;
  return 1.0 - std::exp(-life.stressMortality * std::min(carbonDeficit, 1.0));
}

double seedsPerCrownArea(const LifeHistory& life, bool mastYear) {
  return life.fecundity_m2 * (mastYear ? 1.0 : life.nonMastFraction);
}

double seedProduction(const LifeHistory& life, double crownRadius_m, bool mastYear,
                      double relativeLight) {
  const double crownArea = std::numbers::pi * crownRadius_m * crownRadius_m;
  return seedsPerCrownArea(life, mastYear) * crownArea * std::clamp(relativeLight, 0.0, 1.0);
}

}  // namespace eco
