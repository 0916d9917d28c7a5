// A stand table (docs/validation.md, "The stand table"): a snapshot's trees of at least the
// calipering limit tallied by diameter class, per species and for the whole stand, as a
// forester tallies a stand: stems, basal area and stem volume per hectare, mean height and
// slenderness in each class. stats.csv gives the stand's totals each year; this is how they
// are made up.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/ecology/stand_measures.hpp"
#include "sim/plan/plan_spec.hpp"
#include "sim/run/run_folder.hpp"
#include "sim/run/trees_file.hpp"

namespace eco {

struct DiameterClass {
  double stemsPerHa = 0.0;
  double basalArea_m2PerHa = 0.0;
  double volume_m3PerHa = 0.0;   // form factor x basal area x height, as stats.csv's
  double meanHeight_m = 0.0;     // of the class's trees; 0 where it has none
  double meanSlenderness = 0.0;  // the mean of the trees' height / dbh, both in metres
};

struct StandTable {
  int year = 0;
  double area_ha = 0.0;   // the stems and sums are per hectare of this
  bool ofRegion = false;  // of a region's trees and area, not the whole map's
  double classWidth_cm = 0.0;
  // The snapshot's species, then "all" (the stand).
  std::vector<std::string> rows;
  // classes[row][k] holds the trees of dbh in [from_cm(k), from_cm(k + 1)); every row has
  // the classes up to the stand's thickest tree, none where no tree reaches 10 cm.
  std::vector<std::vector<DiameterClass>> classes;
  // Each row's measures as stats.csv gives them (stems, basal area, quadratic mean diameter,
  // stand density index, volume; not the dominant height, which takes the thinner trees).
  std::vector<StandMeasures> measures;

  double from_cm(std::size_t k) const;
  std::size_t classCount() const { return classes.empty() ? 0 : classes.front().size(); }
  // A row's trees of every class together.
  DiameterClass total(std::size_t row) const;
};

// The snapshot's trees on `area_ha` in classes of `classWidth_cm` from 10 cm up;
// `formFactors` holds each of the snapshot's species' (its speciesNames' order).
StandTable standTable(const TreeSnapshot& snapshot, const std::vector<double>& formFactors,
                      double area_ha, double classWidth_cm);

// The stand tables of a run's snapshots of `years`, per hectare of its map, with its
// species' form factors (the map and the species files read once), a row for each of the
// scenario's species in its order; InputErrors name the snapshot (a year it lacks, a
// species its scenario lacks). Within a region: its trees,
// per hectare of its landscape cells (as a plan's thinning counts them; an InputError at
// the region's key when it misses the map).
std::vector<StandTable> standTablesOfRun(const RunFolder& run, const std::vector<int>& years,
                                         double classWidth_cm,
                                         const std::optional<RegionSpec>& within = {});

// A CSV line per row and class, the stand's as species "all", under this header.
inline constexpr const char* kStandTableCsvHeader =
    "year,species,dbh_from_cm,dbh_to_cm,stems_per_ha,basal_area_m2_per_ha,volume_m3_per_ha,"
    "mean_height_m,mean_slenderness";
// The tables of one or more years under the header: a development over the years.
std::string standTableCsv(const std::vector<StandTable>& tables);
// The same lines without the header, each after `prefix` (compare's run name and a comma).
std::string standTableCsvLines(const StandTable& table, std::string_view prefix = "");
// Each row's measures (StandTable::measures) as a CSV line, after `prefix`, under this
// header (compare's stand_measures.csv, with the run's name first).
inline constexpr const char* kStandMeasuresCsvHeader =
    "year,species,stems_per_ha,basal_area_m2_per_ha,qmd_cm,sdi,volume_m3_per_ha";
std::string standMeasuresCsvLines(const StandTable& table, std::string_view prefix = "");
// For a terminal: a line per class, each species' stems and the stand's measures, and the
// totals last.
std::string standTableText(const StandTable& table);

}  // namespace eco
