// Canopy gaps and their edges (docs/ecology.md, "Gaps and edges"): where a stand's canopy
// is open, and which plants stand there. A gap is an opening in the canopy down to the
// lower layers (Brokaw 1982, Ecology 63: 682); the edge around it reaches out to the stems of
// the canopy trees that border it (Runkle's "expanded gap", Runkle 1982, Ecology 63: 1533).
// Ours, on square cells of the map: the canopy is the crowns of trees at least 10 m tall; a
// cell is in a gap where they cover less than half of the 15 x 15 m around it, and at an
// edge where it is not but lies within 10 m (about a canopy crown's diameter) of a gap.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/ecology/light_grid.hpp"
#include "sim/ecology/plants.hpp"
#include "sim/terrain.hpp"

namespace eco {

inline constexpr double kGapCell_m = kLightColumn_m;  // a cell of the gap map
inline constexpr double kCanopyTreeHeight_m = 10.0;   // trees this tall make the canopy
inline constexpr double kGapCover = 0.5;              // a gap: canopy cover under this...
inline constexpr int kGapNeighbourhoodCells = 1;      // ...over the cell and this many around it
inline constexpr double kEdgeReach_m = 10.0;          // an edge: within this of a gap

enum class CanopyPlace : std::uint8_t { Closed, Edge, Gap, Outside };

// Shares of the landscape's cells (those not Outside), or of a species' stems.
struct CanopyGapShares {
  double gaps = 0.0;         // in a gap
  double gapsOrEdges = 0.0;  // in a gap or at its edge
};

class CanopyGapMap {
 public:
  // The canopy of these plants over the terrain; cells whose centre lies off the landscape
  // (no-data cells) are Outside.
  CanopyGapMap(const Plants& plants, const Terrain& terrain);

  CanopyPlace at(double east_m, double north_m) const;
  CanopyGapShares shares() const;

 private:
  CanopyPlace place(int x, int y) const {
    return places_[static_cast<std::size_t>(y) * width_ + x];
  }

  int width_ = 0, height_ = 0;  // cells; row 0 in the south
  double originEast_m_ = 0.0, originNorth_m_ = 0.0;
  std::vector<CanopyPlace> places_;
};

// Where a species' stems (plants at least 1.3 m tall) stand.
struct GapStems {
  std::int64_t stems = 0;
  CanopyGapShares shares;  // of these stems
};

// One entry per species (`speciesCount` of them, by the plants' species index).
std::vector<GapStems> gapStemsOf(const Plants& plants, const CanopyGapMap& gaps, int speciesCount);

}  // namespace eco
