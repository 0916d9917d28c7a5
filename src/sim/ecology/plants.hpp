// The plants of an ecosystem as parallel arrays (DESIGN.md): one column per attribute, one
// row per plant, kept in order of birth so that every pass over them is deterministic.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace eco {

// How a plant came: from a seed, or planted (sim/plan); planted stock on ground where a
// condition rules its species out, with the planting's survival check, dies in its first year.
enum class PlantOrigin : std::uint8_t { Seeded = 0, Planted = 1, PlantedRuledOut = 2 };

struct Plants {
  std::vector<std::uint64_t> id;      // unique in a run, in order of establishment
  std::vector<std::uint8_t> species;  // index into the run's species list
  // Map position (Grid::cellAt). What follows from it and the id -- the ground's altitude,
  // the grid cell, the tree model's variant seed -- is worked out where it is needed, not
  // kept: a landscape holds 100 million plants, and every byte a plant is 100 MB.
  std::vector<float> east_m, north_m;
  std::vector<std::int32_t> age_years;
  std::vector<float> height_m;
  std::vector<float> crownRadius_m;
  std::vector<float> crownBase_m;          // height of the lowest living branches
  std::vector<float> dbh_m;                // stem diameter at breast height, 0 below 1.3 m
  std::vector<float> vigor;                // 0..1, this year's
  std::vector<float> light;                // fraction of open-sky light at the crown top
  std::vector<float> growthFactor;         // the individual's lasting growth rate, about 1
  std::vector<std::uint16_t> stressYears;  // a sapling's poor years in a row
  std::vector<std::uint8_t> origin;        // PlantOrigin: seeded or planted
  std::vector<std::uint8_t> alive;

  // Calls f(column) for every column, in a fixed order (resizing, compaction, checkpoints).
  template <typename F>
  void forEachColumn(F&& f) {
    visitColumns(f, *this);
  }
  template <typename F>
  void forEachColumn(F&& f) const {
    visitColumns(f, *this);
  }
  // Appends row `i` of other plants, every column.
  void appendRow(const Plants& from, std::size_t i) {
    visitColumns([i](auto& mine, const auto& theirs) { mine.push_back(theirs[i]); }, *this, from);
  }

  std::size_t size() const { return id.size(); }
  void resize(std::size_t n) {
    forEachColumn([n](auto& column) { column.resize(n); });
  }
  // Drops the rows whose alive flag is 0, keeping the order of the others.
  void removeDead();

 private:
  // Calls f with the same column of each of `p...`, column by column.
  template <typename F, typename... Self>
  static void visitColumns(F&& f, Self&... p) {
    f(p.id...), f(p.species...), f(p.east_m...), f(p.north_m...), f(p.age_years...),
        f(p.height_m...), f(p.crownRadius_m...), f(p.crownBase_m...), f(p.dbh_m...), f(p.vigor...),
        f(p.light...), f(p.growthFactor...), f(p.stressYears...), f(p.origin...), f(p.alive...);
  }
};

}  // namespace eco
