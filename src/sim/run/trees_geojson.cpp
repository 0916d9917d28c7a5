#include "sim/run/trees_geojson.hpp"

#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"

namespace eco {

void writeTreesGeoJson(const std::filesystem::path& file, const TreeSnapshot& snapshot,
                       const Grid& grid) {
  std::string text;
  text.reserve(256 + snapshot.trees.size() * 240);
  fmt::format_to(std::back_inserter(text),
                 "{{\"type\":\"FeatureCollection\",\"name\":\"trees_year_{:04d}\",\n",
                 snapshot.year);
  if (grid.epsg != 0)
    fmt::format_to(std::back_inserter(text),
                   "\"crs\":{{\"type\":\"name\",\"properties\":{{\"name\":"
                   "\"urn:ogc:def:crs:EPSG::{}\"}}}},\n",
                   grid.epsg);
  text += "\"features\":[\n";
  std::vector<std::string> names;  // as JSON strings, quoted and escaped
  for (const std::string& name : snapshot.speciesNames)
    names.push_back(nlohmann::json(name).dump());
  for (std::size_t i = 0; i < snapshot.trees.size(); ++i) {
    const TreeRow& t = snapshot.trees[i];
    fmt::format_to(std::back_inserter(text),
                   "{{\"type\":\"Feature\",\"geometry\":{{\"type\":\"Point\",\"coordinates\":"
                   "[{:.3f},{:.3f},{:.3f}]}},\"properties\":{{\"id\":{},\"species\":{},"
                   "\"age\":{},\"height_m\":{:.3f},\"crown_radius_m\":{:.3f},"
                   "\"crown_base_m\":{:.3f},\"dbh_m\":{:.4f},\"vigor\":{:.3f}}}}}{}\n",
                   grid.originEast_m + t.east_m, grid.originNorth_m + t.north_m, t.ground_m, t.id,
                   names[t.species], t.age_years, t.height_m, t.crownRadius_m, t.crownBase_m,
                   t.dbh_m, t.vigor, i + 1 < snapshot.trees.size() ? "," : "");
  }
  text += "]}\n";
  AtomicFile out(file);
  out.write(text);
  out.commit();
}

}  // namespace eco
