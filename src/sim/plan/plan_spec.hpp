// An afforestation plan as a scenario writes it (docs/planning.md): where trees are planted,
// which forests around the land send seeds, which areas are kept open and how the stand is
// thinned. These are the parsed rules; region.hpp places them on a terrain and
// management.hpp carries them out year by year.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "core/error.hpp"

namespace eco {

class TomlTable;

// Where a rule applies, in map metres (the trees CSV's x_m, y_m: east of the westmost cell
// centres, north of the southmost ones).
struct RegionSpec {
  enum class Kind {
    WholeMap,  // no shape given
    Polygon,   // polygon = [[x, y], ...], at least 3 corners
    Line,      // line = [[x, y], ...]: a road or river's centre line, with buffer_m its half width
    Mask,      // mask = "FILE.png": an image of the terrain's size, white (>= half) inside
    Border,    // border_m = W: the band of width W around the outside of the map (seed sources)
  };
  Kind kind = Kind::WholeMap;
  std::vector<glm::dvec2> points;  // Polygon, Line
  std::filesystem::path mask;      // absolute after loading
  double border_m = 0.0;
  double buffer_m = 0.0;  // the shape widened by this distance
  SourceLocation where;   // the key that gave the shape (or the rule's first key)
};

// A species and its share of the trees (planted) or of the canopy (seed source).
struct SpeciesShare {
  std::string species;
  double share = 1.0;
  SourceLocation where;
};

enum class PlantingLayout { Square, Triangular, Contour, Random };

// [[planting]]: a stand planted in a region at the start of a year.
struct Planting {
  RegionSpec region;
  int year = 1;  // planted at the start of this year (1: before the first year grows)
  // What: species with proportions (shares summing to 1), each tree drawn at random by them;
  // or, when `rows` is not empty, a repeating pattern of species row by row.
  std::vector<SpeciesShare> mix;
  std::vector<SpeciesShare> rows;
  PlantingLayout layout = PlantingLayout::Square;
  double spacing_m = 2.0;      // between trees in a row (random: the mean spacing)
  double rowSpacing_m = 2.0;   // between rows (default: the spacing)
  double minDistance_m = 0.0;  // random layout: no two trees closer than this
  double height_m = 0.3;       // of the planted stock
  int stockAge_years = 0;      // of the planted stock
  // Planted trees on ground where a condition rules their species out die in their first
  // year, and the run says how many; without the check they take their chances as seedlings
  // do.
  bool survivalCheck = true;
  SourceLocation where;
  // Every species the planting names, in order of first mention.
  std::vector<std::string> speciesNames() const;
};

// [[seed_source]]: existing forest on or around the map.
struct SeedSource {
  RegionSpec region;
  std::vector<SpeciesShare> mix;  // the canopy's composition, shares summing to 1
  double cover = 0.8;             // share of its ground under crowns, 0..1
  SourceLocation where;
};

// [[exclusion]]: kept open; nothing establishes or is planted there.
struct Exclusion {
  RegionSpec region;
  SourceLocation where;
};

enum class ThinningMethod { FromBelow, FromAbove, RemoveSpecies };

// [[thinning]]: in a region, from a year on every N years (until a year), the trees of at
// least 10 cm dbh are thinned from below or above to a target basal area or stem number, or
// a species is removed.
struct Thinning {
  RegionSpec region;
  int fromYear = 1;
  int everyYears = 0;  // 0: once
  std::optional<int> untilYear;
  ThinningMethod method = ThinningMethod::FromBelow;
  std::optional<double> targetBasalArea_m2PerHa;
  std::optional<double> targetStemsPerHa;
  std::vector<std::string> species;  // the species thinned (removed); empty: every species
  SourceLocation where;
  bool appliesIn(int year) const;
};

// The plan's map (maps/plan): per cell, the rule that applies there, the later of these
// where rules overlap.
enum class PlanMapCode { Nothing = 0, SeedSource = 1, Thinned = 2, Planted = 3, KeptOpen = 4 };
inline constexpr const char* kPlanMapCodeNames[] = {"nothing", "seed source", "thinned", "planted",
                                                    "kept open"};

struct Plan {
  std::vector<Planting> planting;
  std::vector<SeedSource> seedSources;
  std::vector<Exclusion> exclusions;
  std::vector<Thinning> thinning;
  bool empty() const {
    return planting.empty() && seedSources.empty() && exclusions.empty() && thinning.empty();
  }
};

// A rule's region from its table's keys (polygon, line, mask, border_m where allowed,
// buffer_m; a mask relative to `folder`), at the rule's location when it gives no shape (the
// whole map). Also a region a command is given (`stand --region`).
RegionSpec parseRegion(TomlTable& table, const std::filesystem::path& folder, bool borderAllowed,
                       const SourceLocation& rule);
// A region given on a command line as those keys (`--region 'polygon = [[0, 0], [400, 0],
// [400, 300]]'`), a mask relative to `folder`; InputErrors name `option`, the line and the
// key, and a text that gives no shape.
RegionSpec parseRegionOption(std::string_view text, const std::string& option,
                             const std::filesystem::path& folder);

// Reads the scenario's [[planting]], [[seed_source]], [[exclusion]] and [[thinning]] tables
// (paths relative to the scenario's folder); errors name the file, line and key.
Plan parsePlan(TomlTable& root, const std::filesystem::path& scenarioFolder);

}  // namespace eco
