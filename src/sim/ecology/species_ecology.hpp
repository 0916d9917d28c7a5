// A species' niche and life history for the ecosystem simulation (docs/ecology.md): the
// `[ecology]` table of a species file. Tolerance curves map a living condition to a
// suitability in [0, 1]; by default they are derived from the species' Ellenberg indicator
// values (Ellenberg et al. 1991, the EcoMod paper's ref. [16]) by the rules below, and a
// file may replace any of them with its own polyline.
#pragma once

#include <array>
#include <filesystem>
#include <optional>

#include "core/polyline.hpp"

namespace eco {

class TomlTable;

// Ellenberg indicator values; 0 stands for "x", indifferent.
struct Ellenberg {
  int light = 0;           // L, 1 (deep shade) .. 9 (full light)
  int temperature = 0;     // T, 1 (alpine) .. 9 (hottest lowlands)
  int moisture = 0;        // F, 1 (extremely dry) .. 12 (submerged)
  int continentality = 0;  // K, 1 (oceanic) .. 9 (continental)
};

// The living conditions of the EcoMod paper, in the order of ToleranceCurves::all().
enum class Condition { Altitude, Slope, Moisture, Windiness, Sunniness };
inline constexpr int kConditionCount = 5;
const char* toString(Condition condition);

struct ToleranceCurves {
  Polyline altitude_m;  // over altitude in metres
  Polyline slope_deg;   // over slope in degrees
  Polyline moisture;    // over the moisture field, 0..1
  Polyline windiness;   // over the windiness field, 0..1
  Polyline sunniness;   // over the sunniness field, 0..1
  const Polyline& of(Condition c) const;
  Polyline& of(Condition c);
};

// Chapman-Richards growth: value(t) = max (1 - exp(-rate t))^shape.
struct GrowthCurve {
  double max = 1.0;
  double rate = 0.03;  // per year
  double shape = 1.3;
  double at(double years) const;
  // The age at which the curve reaches `value` (its inverse); infinite at or above max.
  double ageOf(double value) const;
};

enum class DispersalVector { Gravity, Animal, Wind };

struct LifeHistory {
  int maxAge_years = 300;
  GrowthCurve height_m;             // height over age at full vigor
  GrowthCurve dbh_m;                // stem diameter at breast height over age at full vigor
  Polyline crownRadius_m;           // crown radius over dbh in metres
  double crownRatio = 0.6;          // crown length / tree height
  double crownTransmittance = 0.1;  // light passing vertically through a crown's centre
  double seedlingHeight_m = 0.15;   // height in the year a seed establishes
  int maturityAge_years = 40;       // first year of seed production
  double seedsPerYear = 30.0;       // viable seeds a mature tree at full vigor sends out
  double germination = 0.3;         // chance a seed on a perfect, lit site establishes
  DispersalVector dispersal = DispersalVector::Gravity;
  double dispersalMean_m = 15.0;  // mean distance of the seed kernel
  double downwindBias = 0.0;      // wind-dispersed: drift downwind per metre travelled
  // A fat-tailed kernel: this share of the seeds travels with the long mean instead (jays
  // caching nuts, updrafts lifting seeds), which sets how fast a species spreads.
  double longDistanceFraction = 0.0;
  double longDistanceMean_m = 0.0;
  double stressVigor = 0.1;      // vigor below this is a year of stress
  int stressYearsTolerated = 5;  // stress years in a row before stress mortality sets in
};

struct Ecology {
  Ellenberg ellenberg;
  ToleranceCurves tolerance;
  Polyline lightResponse;  // vigor allowed by light, over light as a fraction of open sky
  LifeHistory life;
};

// The documented derivations (docs/ecology.md).
// Minimum relative light a plant of light value L lives with (Ellenberg's definitions of L).
double lightCompensation(int light);
Polyline lightResponseFor(int light);
ToleranceCurves deriveTolerances(const Ellenberg& values);

// Reads an [ecology] table; throws InputError at the file, line and key at fault.
Ecology parseEcology(TomlTable& table);
// The [ecology] table of a species file, or nothing when it has none.
std::optional<Ecology> readEcology(const std::filesystem::path& speciesFile);

}  // namespace eco
