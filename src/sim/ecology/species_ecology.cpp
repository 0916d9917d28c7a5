#include "sim/ecology/species_ecology.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/toml_reader.hpp"

namespace eco {
namespace {

// Full suitability between fullLo and fullHi, falling linearly to zero at zeroLo and zeroHi.
Polyline trapezoid(double zeroLo, double fullLo, double fullHi, double zeroHi) {
  return Polyline({{zeroLo, 0.0}, {fullLo, 1.0}, {fullHi, 1.0}, {zeroHi, 0.0}});
}

// Within 1.5 indicator units of the species' value a site is fully suitable; 3.5 units away
// it is unsuitable (Ellenberg values are modes of a species' realised niche, docs/ecology.md).
constexpr double kFullWithin = 1.5, kZeroBeyond = 3.5;

// Mean annual temperature of T = 5 (the submontane belt) and per unit of T (ours: central
// Europe's belts, colline 8-10 C, submontane 6-8 C, montane 4-6 C; docs/ecology.md).
constexpr double kTemperatureOfT5_c = 7.0, kTemperaturePerUnit_c = 1.5;

// Windiness a species bears fully, and where it bears none, from its wind firmness (ours,
// docs/ecology.md): the firmer, the more exposure. CReg of the firmest European trees is
// about 160 (iLand's beech and maple), of spruce 126.
constexpr double kZeroWindinessAtFirmness160 = 0.85, kWindinessPerFirmness = 0.002;
constexpr double kWindinessBand = 0.35;

int ellenbergValue(TomlTable& table, std::string_view key, int highest) {
  if (!table.has(key))
    table.fail(key, "missing Ellenberg value (a number, or \"x\" if indifferent)");
  if (table.isString(key)) {
    if (table.string(key) != "x") table.fail(key, "expected a number or \"x\" (indifferent)");
    return 0;
  }
  return static_cast<int>(table.integer(key, {}, {1, static_cast<double>(highest)}));
}

Allometry allometry(TomlTable& life, std::string_view key) {
  const std::vector<double> ab = life.numbers(key, 2, {}, {0.0, 10.0});
  if (!(ab[0] > 0.0 && ab[1] > 0.0))
    life.fail(key, "expected [a, b] with a, b > 0 (kg = a dbh_cm^b)");
  return {ab[0], ab[1]};
}

GrowthCurve heightCurve(TomlTable& life) {
  const double max = life.number("max_height_m", {}, {0.1, 150.0});
  if (!(max > 0.0)) life.fail("max_height_m", "must be positive");
  const double rate = life.number("height_growth_rate", {}, {1e-4, 1.0});
  const double shape = life.number("height_growth_shape", {}, {0.3, 5.0});
  return {max, rate, shape};
}

DispersalVector dispersalOf(TomlTable& life) {
  const std::string vector = life.string("dispersal");
  if (vector == "gravity") return DispersalVector::Gravity;
  if (vector == "animal") return DispersalVector::Animal;
  if (vector != "wind")
    life.fail("dispersal", "unknown dispersal '" + vector + "' (expected gravity, animal or wind)");
  return DispersalVector::Wind;
}

// Reproduction: fecundity, mast years, the seed kernel and establishment.
void parseReproduction(TomlTable& life, LifeHistory& h) {
  h.maturityAge_years = static_cast<int>(life.integer("maturity_age_years", {}, {0, 10000}));
  h.fecundity_m2 = life.number("fecundity_per_m2", {}, {0.0, 100000.0});
  h.mastIntervalYears =
      static_cast<int>(life.integer("mast_interval_years", h.mastIntervalYears, {1, 50}));
  h.nonMastFraction = life.number("non_mast_fraction", h.nonMastFraction, {0.0, 1.0});
  h.germination = life.number("germination", h.germination, {0.0, 1.0});
  h.litterEstablishment = life.number("litter_establishment", h.litterEstablishment, {0.0, 1.0});
  h.swardEstablishment = life.number("sward_establishment", h.swardEstablishment, {0.0, 1.0});
  h.seedlingHeight_m = life.number("seedling_height_m", h.seedlingHeight_m, {0.01, 2.0});
  if (h.seedlingHeight_m >= h.height_m.max())
    life.fail("seedling_height_m", "must be below max_height_m");
  h.dispersal = dispersalOf(life);
  h.dispersalMean_m = life.number("dispersal_mean_m", {}, {0.01, 100000.0});
  h.downwindBias = life.number("downwind_bias", h.downwindBias, {0.0, 1.0});
  if (h.downwindBias > 0.0 && h.dispersal != DispersalVector::Wind)
    life.fail("downwind_bias", "only wind-dispersed species drift downwind");
  h.longDistanceFraction =
      life.number("long_distance_fraction", h.longDistanceFraction, {0.0, 1.0});
  if (h.longDistanceFraction > 0.0) {
    h.longDistanceMean_m = life.number("long_distance_mean_m", {}, {0.01, 100000.0});
    if (h.longDistanceMean_m <= h.dispersalMean_m)
      life.fail("long_distance_mean_m", "must be longer than dispersal_mean_m");
  }
}

LifeHistory parseLife(TomlTable& life) {
  LifeHistory h;
  h.maxAge_years = static_cast<int>(life.integer("max_age_years", {}, {1, kLongestLife_years}));
  h.height_m = heightCurve(life);
  h.formFactor = life.number("form_factor", {}, {0.1, 1.0});
  h.foliage = allometry(life, "foliage_biomass");
  h.stem = allometry(life, "stem_biomass");
  h.branches = allometry(life, "branch_biomass");
  h.coarseRoots = allometry(life, "coarse_root_biomass");
  h.specificLeafArea = life.number("specific_leaf_area_m2_per_kg", {}, {0.5, 100.0});
  h.shadeLeafMassRatio = life.number("shade_leaf_mass_ratio", h.shadeLeafMassRatio, {0.1, 1.0});
  h.leafTurnover = life.number("leaf_turnover_per_year", {}, {0.01, 1.0});
  h.fineRootFoliageRatio = life.number("fine_root_foliage_ratio", {}, {0.0, 10.0});
  h.fineRootTurnover = life.number("fine_root_turnover_per_year", {}, {0.0, 1.0});
  const std::vector<double> crown = life.numbers("crown_diameter_silva", 4, {}, {-10.0, 10.0});
  std::copy(crown.begin(), crown.end(), h.crownDiameterSilva.begin());
  h.crownRatio = life.number("crown_ratio", {}, {0.05, 1.0});
  h.saplingHeightDiameter =
      life.number("sapling_height_diameter", h.saplingHeightDiameter, {10.0, 400.0});
  h.maxHeightDiameter = life.number("max_height_diameter", h.maxHeightDiameter, {10.0, 400.0});
  h.lightUseEfficiency = life.number("light_use_efficiency", {}, {1e-3, 100.0});
  if (life.has("aging")) {
    const std::vector<double> aging = life.numbers("aging", 2, {}, {1e-3, 100.0});
    h.aging = {aging[0], aging[1]};
  }
  h.intrinsicSurvival = life.number("intrinsic_survival", h.intrinsicSurvival, {1e-6, 1.0});
  h.stressMortality = life.number("stress_mortality", h.stressMortality, {0.0, 100.0});
  h.saplingStressYears = static_cast<int>(
      life.integer("sapling_stress_years", h.saplingStressYears, {1, kMostSaplingStressYears}));
  h.saplingStressThreshold =
      life.number("sapling_stress_threshold", h.saplingStressThreshold, {0.0, 1.0});
  parseReproduction(life, h);
  life.finish();
  return h;
}

}  // namespace

const char* toString(Condition condition) {
  switch (condition) {
    case Condition::Altitude:
      return "altitude";
    case Condition::Slope:
      return "slope";
    case Condition::Moisture:
      return "moisture";
    case Condition::Windiness:
      break;
  }
  return "windiness";
}

const Polyline& ToleranceCurves::of(Condition c) const {
  return const_cast<ToleranceCurves&>(*this).of(c);
}

Polyline& ToleranceCurves::of(Condition c) {
  switch (c) {
    case Condition::Altitude:
      return altitude_m;
    case Condition::Slope:
      return slope_deg;
    case Condition::Moisture:
      return moisture;
    case Condition::Windiness:
      break;
  }
  return windiness;
}

double Allometry::at(double dbh_cm) const {
  // In single precision (kGrowthPrecision): every tree, every year.
  return a * std::pow(static_cast<float>(dbh_cm), static_cast<float>(b));
}

GrowthCurve::GrowthCurve(double max, double rate_per_year, double shape)
    : max_(max),
      rate_(rate_per_year),
      shape_(shape),
      inverseShape_(static_cast<float>(1.0 / shape)),
      yearDecay_(static_cast<float>(std::exp(-rate_per_year))),
      yearGain_(static_cast<float>(-std::expm1(-rate_per_year))) {}

double GrowthCurve::at(double years) const {
  if (years <= 0.0) return 0.0;
  return max_ * std::pow(1.0 - std::exp(-rate_ * years), shape_);
}

double GrowthCurve::yearAfter(double value) const {
  if (value >= max_) return max_;
  // In single precision (kGrowthPrecision): every plant, every year. 1 - (1 - progress)
  // decay as (1 - decay) + decay progress, which a young plant's small progress does not
  // lose to cancellation.
  const float progress = std::pow(static_cast<float>(std::max(value, 0.0) / max_), inverseShape_);
  return max_ * std::pow(yearGain_ + yearDecay_ * progress, static_cast<float>(shape_));
}

double lightCompensation(int light) {
  // Ellenberg's definitions: L3 "mostly below 5 % relative light", L5 "rarely below 10 %",
  // L7 "rarely below 30 %", L9 "rarely below 50 %"; L1 deep shade. Indifferent reads as L5.
  static const Polyline minimumLight({{1, 0.005}, {3, 0.02}, {5, 0.10}, {7, 0.30}, {9, 0.50}});
  return minimumLight(light == 0 ? 5 : light);
}

Polyline lightResponseFor(int light) {
  const double c = lightCompensation(light);
  return Polyline({{c, 0.0}, {c + 0.3, 1.0}});
}

double meanAnnualTemperatureOf(double temperatureValue) {
  return kTemperatureOfT5_c + kTemperaturePerUnit_c * (temperatureValue - 5.0);
}

double altitudeOfTemperature(double temperature_c, const Climate& climate) {
  return climate.temperatureAltitude_m +
         (climate.meanAnnualTemperature_c - temperature_c) / climate.lapseRate_K_per_m;
}

ToleranceCurves deriveTolerances(const Ellenberg& e, double windFirmness, const Climate& climate) {
  ToleranceCurves t;
  // Moisture: the site's moisture number on Ellenberg's F scale against the species' F.
  if (e.moisture == 0) {
    t.moisture = Polyline::constant(1.0);
  } else {
    t.moisture = trapezoid(e.moisture - kZeroBeyond, e.moisture - kFullWithin,
                           e.moisture + kFullWithin, e.moisture + kZeroBeyond);
  }
  // Temperature: T's mean annual temperature, and the altitudes that have it in this
  // climate (warmer is lower: the trapezoid over altitude runs from the hot end).
  if (e.temperature == 0 || climate.lapseRate_K_per_m <= 0.0) {
    t.altitude_m = Polyline::constant(1.0);
  } else {
    auto altitude = [&](double value) {
      return altitudeOfTemperature(meanAnnualTemperatureOf(value), climate);
    };
    t.altitude_m =
        trapezoid(altitude(e.temperature + kZeroBeyond), altitude(e.temperature + kFullWithin),
                  altitude(e.temperature - kFullWithin), altitude(e.temperature - kZeroBeyond));
  }
  // Exposure: the firmer the stem and roots against wind, the more windiness is borne.
  const double zero =
      std::min(1.0, kZeroWindinessAtFirmness160 + kWindinessPerFirmness * (windFirmness - 160.0));
  t.windiness = Polyline({{zero - kWindinessBand, 1.0}, {zero, 0.0}});
  // Slope has no indicator value: soils thin out on steep ground (files set their own).
  t.slope_deg = Polyline({{35.0, 1.0}, {65.0, 0.0}});
  return t;
}

ToleranceCurves Ecology::tolerances(const Climate& climate) const {
  ToleranceCurves t = deriveTolerances(ellenberg, windFirmness, climate);
  for (int i = 0; i < kConditionCount; ++i)
    if (toleranceOverride[i]) t.of(static_cast<Condition>(i)) = *toleranceOverride[i];
  return t;
}

double Ecology::lightCompensation() const {
  return eco::lightCompensation(ellenberg.light);
}

Ecology parseEcology(TomlTable& table) {
  Ecology ecology;
  std::optional<TomlTable> values = table.table("ellenberg");
  if (!values)
    table.fail("ellenberg", "missing table ellenberg = { light, temperature, moisture }");
  Ellenberg& e = ecology.ellenberg;
  e.light = ellenbergValue(*values, "light", 9);
  e.temperature = ellenbergValue(*values, "temperature", 9);
  e.moisture = ellenbergValue(*values, "moisture", 12);
  values->finish();
  ecology.windFirmness = table.number("wind_firmness", {}, {1.0, 1000.0});

  ecology.lightResponse = table.has("light_response") ? table.polyline("light_response", {0.0, 1.0})
                                                      : lightResponseFor(e.light);
  if (std::optional<TomlTable> tolerance = table.table("tolerance")) {
    // The keys of ToleranceCurves' members, in Condition's order.
    static constexpr const char* kKeys[kConditionCount] = {"altitude_m", "slope_deg", "moisture",
                                                           "windiness"};
    for (int i = 0; i < kConditionCount; ++i)
      if (tolerance->has(kKeys[i]))
        ecology.toleranceOverride[i] = tolerance->polyline(kKeys[i], {0.0, 1.0});
    tolerance->finish();
  }
  std::optional<TomlTable> life = table.table("life");
  if (!life) table.fail("life", "missing table [ecology.life]");
  ecology.life = parseLife(*life);
  table.finish();
  return ecology;
}

std::optional<Ecology> readEcology(const std::filesystem::path& speciesFile) {
  TomlDocument document = TomlDocument::load(speciesFile);
  TomlTable root = document.root();
  std::optional<TomlTable> ecology = root.table("ecology");
  if (!ecology) return std::nullopt;
  return parseEcology(*ecology);
}

}  // namespace eco
