#include "sim/ecology/species_ecology.hpp"

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

int ellenbergValue(TomlTable& table, std::string_view key, int highest) {
  if (!table.has(key))
    table.fail(key, "missing Ellenberg value (a number, or \"x\" if indifferent)");
  if (table.isString(key)) {
    if (table.string(key) != "x") table.fail(key, "expected a number or \"x\" (indifferent)");
    return 0;
  }
  return static_cast<int>(table.integer(key, {}, {1, static_cast<double>(highest)}));
}

GrowthCurve growthCurve(TomlTable& life, const std::string& prefix, std::string_view maxKey,
                        Range maxRange) {
  GrowthCurve curve;
  curve.max = life.number(maxKey, {}, maxRange);
  if (!(curve.max > 0.0)) life.fail(maxKey, "must be positive");
  curve.rate = life.number(prefix + "_growth_rate", {}, {1e-4, 1.0});
  curve.shape = life.number(prefix + "_growth_shape", {}, {0.5, 5.0});
  return curve;
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
      return "windiness";
    case Condition::Sunniness:
      return "sunniness";
  }
  return "?";
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
      return windiness;
    case Condition::Sunniness:
      break;
  }
  return sunniness;
}

double GrowthCurve::at(double years) const {
  if (years <= 0.0) return 0.0;
  return max * std::pow(1.0 - std::exp(-rate * years), shape);
}

double GrowthCurve::ageOf(double value) const {
  if (value <= 0.0) return 0.0;
  if (value >= max) return std::numeric_limits<double>::infinity();
  return -std::log(1.0 - std::pow(value / max, 1.0 / shape)) / rate;
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

ToleranceCurves deriveTolerances(const Ellenberg& e) {
  ToleranceCurves t;
  // Moisture: the site's moisture number is F = 1 + 8 m for the moisture field m in [0, 1].
  if (e.moisture == 0) {
    t.moisture = Polyline::constant(1.0);
  } else {
    auto m = [](double f) { return (f - 1.0) / 8.0; };
    t.moisture = trapezoid(m(e.moisture - kZeroBeyond), m(e.moisture - kFullWithin),
                           m(e.moisture + kFullWithin), m(e.moisture + kZeroBeyond));
  }
  // Temperature by altitude: vegetation belts of central Europe, one T unit per 450 m,
  // T = 6 at 300 m (colline), 5 submontane, 4 montane at about 1200 m.
  if (e.temperature == 0) {
    t.altitude_m = Polyline::constant(1.0);
  } else {
    auto altitude = [](double temperature) { return 300.0 + 450.0 * (6.0 - temperature); };
    t.altitude_m =
        trapezoid(altitude(e.temperature + kZeroBeyond), altitude(e.temperature + kFullWithin),
                  altitude(e.temperature - kFullWithin), altitude(e.temperature - kZeroBeyond));
  }
  // Exposure: continental species (high K) bear wind, frost and drought on exposed sites.
  if (e.continentality == 0) {
    t.windiness = Polyline::constant(1.0);
  } else {
    const double full = 0.3 + 0.07 * e.continentality;
    t.windiness = Polyline({{full, 1.0}, {full + 0.4, 0.0}});
  }
  // Terrain shade: a site darker than the species' light minimum cannot carry it.
  const double c = lightCompensation(e.light);
  t.sunniness = Polyline({{c, 0.0}, {c + 0.3, 1.0}});
  // Slope has no Ellenberg value: soils thin out on steep ground (files set their own).
  t.slope_deg = Polyline({{35.0, 1.0}, {65.0, 0.0}});
  return t;
}

Ecology parseEcology(TomlTable& table) {
  Ecology ecology;
  std::optional<TomlTable> values = table.table("ellenberg");
  if (!values)
    table.fail("ellenberg",
               "missing table ellenberg = { light, temperature, moisture, continentality }");
  Ellenberg& e = ecology.ellenberg;
  e.light = ellenbergValue(*values, "light", 9);
  e.temperature = ellenbergValue(*values, "temperature", 9);
  e.moisture = ellenbergValue(*values, "moisture", 12);
  e.continentality = ellenbergValue(*values, "continentality", 9);
  values->finish();

  ecology.tolerance = deriveTolerances(e);
  ecology.lightResponse = table.has("light_response") ? table.polyline("light_response", {0.0, 1.0})
                                                      : lightResponseFor(e.light);
  if (std::optional<TomlTable> tolerance = table.table("tolerance")) {
    const char* keys[kConditionCount] = {"altitude_m", "slope_deg", "moisture", "windiness",
                                         "sunniness"};
    for (int i = 0; i < kConditionCount; ++i)
      if (tolerance->has(keys[i]))
        ecology.tolerance.of(static_cast<Condition>(i)) = tolerance->polyline(keys[i], {0.0, 1.0});
    tolerance->finish();
  }

  std::optional<TomlTable> life = table.table("life");
  if (!life) table.fail("life", "missing table [ecology.life]");
  LifeHistory& h = ecology.life;
  h.maxAge_years = static_cast<int>(life->integer("max_age_years", {}, {1, 10000}));
  h.height_m = growthCurve(*life, "height", "max_height_m", {0.1, 150.0});
  h.dbh_m = growthCurve(*life, "dbh", "max_dbh_m", {0.001, 10.0});
  h.crownRadius_m = life->polyline("crown_radius_m", {0.0, 50.0});
  h.crownRatio = life->number("crown_ratio", {}, {0.05, 1.0});
  h.crownTransmittance = life->number("crown_transmittance", {}, {0.0, 1.0});
  h.seedlingHeight_m = life->number("seedling_height_m", h.seedlingHeight_m, {0.01, 2.0});
  if (h.seedlingHeight_m >= h.height_m.max)
    life->fail("seedling_height_m", "must be below max_height_m");
  h.maturityAge_years = static_cast<int>(life->integer("maturity_age_years", {}, {0, 10000}));
  h.seedsPerYear = life->number("seeds_per_year", {}, {0.0, 100000.0});
  h.germination = life->number("germination", {}, {0.0, 1.0});
  const std::string vector = life->string("dispersal");
  if (vector == "gravity")
    h.dispersal = DispersalVector::Gravity;
  else if (vector == "animal")
    h.dispersal = DispersalVector::Animal;
  else if (vector == "wind")
    h.dispersal = DispersalVector::Wind;
  else
    life->fail("dispersal",
               "unknown dispersal '" + vector + "' (expected gravity, animal or wind)");
  h.dispersalMean_m = life->number("dispersal_mean_m", {}, {0.01, 100000.0});
  h.downwindBias = life->number("downwind_bias", 0.0, {0.0, 1.0});
  if (h.downwindBias > 0.0 && h.dispersal != DispersalVector::Wind)
    life->fail("downwind_bias", "only wind-dispersed species drift downwind");
  h.longDistanceFraction = life->number("long_distance_fraction", 0.0, {0.0, 1.0});
  if (h.longDistanceFraction > 0.0) {
    h.longDistanceMean_m = life->number("long_distance_mean_m", {}, {0.01, 100000.0});
    if (h.longDistanceMean_m <= h.dispersalMean_m)
      life->fail("long_distance_mean_m", "must be longer than dispersal_mean_m");
  }
  h.stressVigor = life->number("stress_vigor", h.stressVigor, {0.0, 1.0});
  h.stressYearsTolerated =
      static_cast<int>(life->integer("stress_years_tolerated", h.stressYearsTolerated, {1, 1000}));
  life->finish();
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
