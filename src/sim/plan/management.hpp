// Carrying out a scenario's plan on an ecosystem (docs/planning.md): the areas kept open and
// the seed sources are installed once; each year's plantings go in at the start of their
// year and its thinnings come at the end of it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim/ecology/ecosystem.hpp"
#include "sim/plan/plan_spec.hpp"
#include "sim/plan/region.hpp"

namespace eco {

// What the plan did in one year, per species.
struct PlanYear {
  std::vector<std::int64_t> planted, removed;
  std::vector<double> removedVolume_m3;  // stem volume of the removed trees of >= 10 cm
  Plants removedPlants;                  // the trees removed, for removed/year_NNNN.csv
  explicit PlanYear(std::size_t species = 0)
      : planted(species, 0), removed(species, 0), removedVolume_m3(species, 0.0) {}
};

// The species index of a name the scenario's plan uses; an InputError at `where` naming the
// scenario's species when none is called so.
int planSpeciesIndex(const std::string& name, const SourceLocation& where,
                     const std::vector<EcosystemSpecies>& species);

class Management {
 public:
  // Places every rule's region on the terrain and finds its species (InputErrors at the
  // scenario's lines), then keeps the exclusions open and adds the seed sources to the
  // ecosystem, which must outlive this.
  Management(const Plan& plan, Ecosystem& ecosystem, std::uint64_t seed);

  // The plantings of `year` (before it is stepped). `warn` hears what the user should know:
  // stock planted where a condition rules its species out, a layout that fell back.
  void plantAtStartOf(int year, PlanYear& done,
                      const std::function<void(const std::string&)>& warn);
  // The thinnings of `year` (after it is stepped).
  void thinAtEndOf(int year, PlanYear& done);

  // The plan's map: a PlanMapCode per cell.
  Field planMap() const;

 private:
  struct PlacedPlanting {
    const Planting* rule;
    Region region;
    std::vector<int> mix, rows;  // species indices
  };
  struct PlacedThinning {
    const Thinning* rule;
    Region region;
    double area_ha;
    std::vector<std::uint8_t> thinned;  // per species: its trees may be taken
  };
  Ecosystem& ecosystem_;
  std::uint64_t seed_;
  std::vector<PlacedPlanting> plantings_;
  std::vector<PlacedThinning> thinnings_;
  std::vector<Region> exclusions_, seedSources_;
};

}  // namespace eco
