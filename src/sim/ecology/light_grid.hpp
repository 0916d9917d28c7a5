// Light in the forest (docs/ecology.md, "Light"): crowns fill the canopy from the top, as in
// the perfect plasticity approximation (Purves et al. 2008, PNAS 105: 15386; Strigul et al.
// 2008, Ecol. Monogr. 78: 523).
// The map is cut into square columns of kLightColumn_m. Light enters each column from above
// at the terrain's light (sunniness, relative to open level ground). Each crown is a flat
// disc of leaves at its top, spread over the columns its projection covers; in every column
// the crowns take light in order of height, tallest first, each absorbing on its own area by
// Beer's law, 1 - exp(-k LAI) with k = 0.5, from what the taller crowns left. Light is mixed
// across a column, so a crown shares it with the neighbours whose crowns overlap its own
// only when they are taller: competition for light is size-asymmetric, as in a real canopy,
// where the taller tree takes the space.
// Cost grows with the number of crowns (a sort per column), not with rays or a canopy's
// volume; the columns, fixed in metres, make the result independent of the terrain's cell
// size.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/buffer.hpp"
#include "sim/grid.hpp"

namespace eco {

inline constexpr double kLightColumn_m = 5.0;
inline constexpr double kLeafExtinction = 0.5;  // Beer's law k for a random leaf angle distribution

// A crown as the light grid sees it: a disc of leaves at the top of the tree. One without
// leaves takes no light and casts no shade.
struct CrownShape {
  float east_m = 0.0f, north_m = 0.0f;  // map coordinates of the stem
  float radius_m = 0.5f;
  float top_m = 1.0f;  // height above the ground
  float leafArea_m2 = 0.0f;
};

// The light grid draws no crown narrower than this.
inline constexpr float kMinCrownRadius_m = 0.05f;

// A year's crowns read from columns, not copied: the ecosystem's plants' own position,
// radius and height columns (one row a plant), the rows of the plants that are crowns (its
// trees, in order: the sapling layer below them casts no shade), and each crown's leaf area.
// A landscape's 100 million plants are neither copied into crown records each year nor given
// room as crowns when most of them are saplings.
struct CrownColumns {
  std::span<const float> east_m, north_m, radius_m, top_m;  // per row
  std::span<const std::uint32_t> rows;                      // per crown: its row
  std::span<const float> leafArea_m2;                       // per crown
  std::size_t size() const { return rows.size(); }
  // Crown k, at least kMinCrownRadius_m across.
  CrownShape operator[](std::size_t k) const {
    const std::size_t i = rows[k];
    return {east_m[i], north_m[i], std::max(radius_m[i], kMinCrownRadius_m), top_m[i],
            leafArea_m2[k]};
  }
};

class LightGrid {
 public:
  // Columns covering the terrain grid; `topLight` (one value per terrain cell) is the light
  // above the canopy through the terrain, relative to open level ground.
  LightGrid(const Grid& terrain, const Field& topLight);

  // This year's light through these crowns (any order; ties in height go to the earlier).
  void compute(const CrownColumns& crowns);
  // The same of crowns as records (a few crowns: a scene, a test), copied into columns.
  void compute(const std::vector<CrownShape>& crowns);

  // Frees what only absorbed() reads, the crowns' entries, until the next compute(); the
  // light through the canopy is kept. A landscape's entries take half a gigabyte that the
  // rest of its year, once its trees have grown, does not need.
  void releaseAbsorbed();
  // Light absorbed by crown k of the last compute(), in m2 of open-sky light (not after
  // releaseAbsorbed()).
  // The sum of its entries' light, worked out when asked: each crown is asked once a year,
  // and an array of the sums took 8 bytes a plant.
  double absorbed(std::size_t crown) const;
  // What the same crown would absorb standing alone on open level ground.
  static double absorbedInTheOpen(const CrownShape& crown);
  // Light (a fraction of open level ground's) at a height above the ground: what the crowns
  // with their tops above it leave.
  double lightAt(double east_m, double north_m, double height_m) const;
  // The same on the ground, below every crown.
  double groundLightAt(double east_m, double north_m) const;
  // In a column (columnAt): on the ground, and above every crown (the terrain's light).
  double groundLightInColumn(long column) const;
  double skyLightInColumn(long column) const { return topLight_[column]; }
  // The lowest height in [from_m, top_m] where the light beside a crown -- the mean over
  // the four columns `reach_m` east, north, west and south of the stem -- reaches at least
  // `light` (crown pruning: a lower branch lives on the light that comes in from the side
  // and from above, not on what its own crown lets through); `top_m` if none below it does.
  double heightWithSideLight(double east_m, double north_m, double reach_m, double from_m,
                             double top_m, double light) const;
  // How far from its stem a crown's light columns lie beyond its own footprint: a column's
  // far corner is its side times sqrt 2 from its near side.
  static double beyondCrown_m(double crownRadius_m);

  // The column holding a map position (clamped to the map), numbered row by row from the
  // south-west corner. Inline: the plants are kept in order of it, so it is worked out for
  // every new plant's search among them (Ecosystem::settleNewcomers).
  long columnAt(double east_m, double north_m) const {
    return static_cast<long>(columnYAt(north_m)) * columnsX_ + columnXAt(east_m);
  }
  // Its two parts, the column's place west to east and south to north: columnAt is
  // columnY * columnsX() + columnX.
  int columnXAt(double east_m) const {
    return std::clamp(static_cast<int>(std::floor((east_m - originEast_m_) / kLightColumn_m)), 0,
                      columnsX_ - 1);
  }
  int columnYAt(double north_m) const {
    return std::clamp(static_cast<int>(std::floor((north_m - originNorth_m_) / kLightColumn_m)), 0,
                      columnsY_ - 1);
  }
  int columnsX() const { return columnsX_; }
  int columnsY() const { return columnsY_; }

 private:
  struct Footprint {
    std::int32_t column;
    float weight;  // share of the crown's projection over the column
  };
  // A crown's entry in a column: the crown and its share of the crown's projection there
  // until its column's pass has read them, then the light the crown takes there. The one
  // overwrites the other, as no pass needs both: a landscape's year has some 80 million
  // entries, and a separate array for the light took 8 bytes more each, one for the crown 4.
  struct Share {
    std::uint32_t crown;
    float weight;
  };
  union Entry {
    Share share;
    double taken;
  };
  // A crown's place in a column's light profile: its top, and the light it leaves below it.
  // Until the column's pass has read it, the place holds the crown's entry instead of the
  // light: the places are sorted by top as they will stay, with no other array in column
  // order and no lookup of each top while sorting.
  struct Layer {
    float top_m;
    union {
      float lightBelow;
      std::uint32_t entry;
    };
  };
  void footprint(const CrownShape& crown, std::vector<Footprint>& out) const;
  double lightInColumn(long column, double height_m) const;
  // The column's profile, tallest crown first.
  const Layer* layersBegin(long column) const { return layers_.data() + columnStart_[column]; }
  const Layer* layersEnd(long column) const { return layers_.data() + columnStart_[column + 1]; }

  int columnsX_ = 0, columnsY_ = 0;
  double originEast_m_ = 0.0, originNorth_m_ = 0.0;  // south-west corner of the columns
  std::vector<float> topLight_;                      // per column
  // Per column: its crowns' layers, tallest first (CSR).
  std::vector<std::size_t> columnStart_;
  Buffer<Layer> layers_;
  // compute()'s working arrays, kept from one call to the next unless releaseAbsorbed() freed
  // them (the ecosystem does, each year once its trees have grown): allocated afresh, the
  // vectors zeroed them again after the kernel (docs/performance.md, "Working arrays kept from
  // year to year"). Each is written before it is read. Per crown: where its entries start (32
  // bits: a landscape has tens of millions of crowns). Per entry, in crown order: the entry.
  Buffer<std::uint32_t> crownStart_;
  Buffer<Entry> entries_;
};

}  // namespace eco
