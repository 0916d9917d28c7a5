#include "sim/ecology/canopy_gaps.hpp"

#include <algorithm>
#include <cmath>

#include "sim/ecology/growth.hpp"

namespace eco {
namespace {

// Canopy cover is measured on this many points along each side of a cell: a point is
// covered when it lies inside any canopy crown, so overlapping crowns count once.
constexpr int kSamples = 4;

}  // namespace

CanopyGapMap::CanopyGapMap(const Plants& p, const Terrain& terrain)
    : width_(std::max(
          1, static_cast<int>(std::ceil(terrain.grid.width * terrain.grid.dx_m / kGapCell_m)))),
      height_(std::max(
          1, static_cast<int>(std::ceil(terrain.grid.height * terrain.grid.dy_m / kGapCell_m)))),
      originEast_m_(-0.5 * terrain.grid.dx_m),
      originNorth_m_(-0.5 * terrain.grid.dy_m) {
  const int pointsX = width_ * kSamples, pointsY = height_ * kSamples;
  const double step = kGapCell_m / kSamples;
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(pointsX) * pointsY, 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.height_m[i] < kCanopyTreeHeight_m) continue;
    const double r = p.crownRadius_m[i];
    const double east = p.east_m[i] - originEast_m_, north = p.north_m[i] - originNorth_m_;
    // Points (k + 0.5) step within the crown's bounding square.
    const int x0 = std::max(0, static_cast<int>(std::ceil((east - r) / step - 0.5)));
    const int x1 = std::min(pointsX - 1, static_cast<int>(std::floor((east + r) / step - 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::ceil((north - r) / step - 0.5)));
    const int y1 = std::min(pointsY - 1, static_cast<int>(std::floor((north + r) / step - 0.5)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double de = (x + 0.5) * step - east, dn = (y + 0.5) * step - north;
        if (de * de + dn * dn <= r * r) covered[static_cast<std::size_t>(y) * pointsX + x] = 1;
      }
  }
  // Each cell's cover, and whether it lies on the landscape.
  std::vector<double> cover(static_cast<std::size_t>(width_) * height_, 0.0);
  places_.assign(cover.size(), CanopyPlace::Closed);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const std::size_t c = static_cast<std::size_t>(y) * width_ + x;
      const long cell = terrain.grid.cellAt(originEast_m_ + (x + 0.5) * kGapCell_m,
                                            originNorth_m_ + (y + 0.5) * kGapCell_m);
      if (cell < 0 || terrain.isOutside(static_cast<std::size_t>(cell))) {
        places_[c] = CanopyPlace::Outside;
        continue;
      }
      int points = 0;
      for (int sy = 0; sy < kSamples; ++sy)
        for (int sx = 0; sx < kSamples; ++sx)
          points +=
              covered[static_cast<std::size_t>(y * kSamples + sy) * pointsX + x * kSamples + sx];
      cover[c] = static_cast<double>(points) / (kSamples * kSamples);
    }
  // Gaps: the cover over the neighbourhood (its cells on the landscape) under kGapCover.
  const int n = kGapNeighbourhoodCells;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const std::size_t c = static_cast<std::size_t>(y) * width_ + x;
      if (places_[c] == CanopyPlace::Outside) continue;
      double sum = 0.0;
      int cells = 0;
      for (int ny = std::max(0, y - n); ny <= std::min(height_ - 1, y + n); ++ny)
        for (int nx = std::max(0, x - n); nx <= std::min(width_ - 1, x + n); ++nx) {
          const std::size_t k = static_cast<std::size_t>(ny) * width_ + nx;
          if (places_[k] == CanopyPlace::Outside) continue;
          sum += cover[k];
          ++cells;
        }
      if (sum < kGapCover * cells) places_[c] = CanopyPlace::Gap;
    }
  // Edges: closed cells whose centre lies within kEdgeReach_m of a gap cell's centre.
  const int reach = static_cast<int>(std::floor(kEdgeReach_m / kGapCell_m));
  const double reachCells = kEdgeReach_m / kGapCell_m;
  std::vector<CanopyPlace> withEdges = places_;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      if (place(x, y) != CanopyPlace::Closed) continue;
      bool nearGap = false;
      for (int ny = std::max(0, y - reach); ny <= std::min(height_ - 1, y + reach) && !nearGap;
           ++ny)
        for (int nx = std::max(0, x - reach); nx <= std::min(width_ - 1, x + reach); ++nx)
          if (place(nx, ny) == CanopyPlace::Gap &&
              (nx - x) * (nx - x) + (ny - y) * (ny - y) <= reachCells * reachCells) {
            nearGap = true;
            break;
          }
      if (nearGap) withEdges[static_cast<std::size_t>(y) * width_ + x] = CanopyPlace::Edge;
    }
  places_ = std::move(withEdges);
}

CanopyPlace CanopyGapMap::at(double east_m, double north_m) const {
  const int x = static_cast<int>(std::floor((east_m - originEast_m_) / kGapCell_m));
  const int y = static_cast<int>(std::floor((north_m - originNorth_m_) / kGapCell_m));
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return CanopyPlace::Outside;
  return place(x, y);
}

namespace {

// Adds one place to the shares' counts (divided by the total afterwards).
void count(CanopyGapShares& shares, CanopyPlace place) {
  shares.gaps += place == CanopyPlace::Gap;
  shares.gapsOrEdges += place == CanopyPlace::Gap || place == CanopyPlace::Edge;
}

void divide(CanopyGapShares& shares, std::int64_t total) {
  if (total == 0) return;
  shares.gaps /= static_cast<double>(total);
  shares.gapsOrEdges /= static_cast<double>(total);
}

}  // namespace

CanopyGapShares CanopyGapMap::shares() const {
  CanopyGapShares shares;
  std::int64_t landscape = 0;
  for (const CanopyPlace place : places_)
    if (place != CanopyPlace::Outside) {
      ++landscape;
      count(shares, place);
    }
  divide(shares, landscape);
  return shares;
}

std::vector<GapStems> gapStemsOf(const Plants& p, const CanopyGapMap& gaps, int speciesCount) {
  std::vector<GapStems> stems(static_cast<std::size_t>(speciesCount));
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.height_m[i] < kBreastHeight_m) continue;
    GapStems& s = stems[p.species[i]];
    ++s.stems;
    count(s.shares, gaps.at(p.east_m[i], p.north_m[i]));
  }
  for (GapStems& s : stems) divide(s.shares, s.stems);
  return stems;
}

}  // namespace eco
