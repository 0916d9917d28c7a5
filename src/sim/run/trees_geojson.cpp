#include "sim/run/trees_geojson.hpp"

#include <iterator>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace eco {

TreesGeoJsonWriter::TreesGeoJsonWriter(const std::filesystem::path& file, const Grid& grid,
                                       int year)
    : out_(file), grid_(grid) {
  std::string text =
      fmt::format("{{\"type\":\"FeatureCollection\",\"name\":\"trees_year_{:04d}\",\n", year);
  if (grid.epsg != 0)
    fmt::format_to(std::back_inserter(text),
                   "\"crs\":{{\"type\":\"name\",\"properties\":{{\"name\":"
                   "\"urn:ogc:def:crs:EPSG::{}\"}}}},\n",
                   grid.epsg);
  text += "\"features\":[";
  out_.write(text);
}

void TreesGeoJsonWriter::write(std::span<const TreeRow> rows,
                               const std::vector<std::string>& speciesNames) {
  // The species as JSON strings, quoted and escaped; a later batch may name more.
  for (std::size_t s = quotedNames_.size(); s < speciesNames.size(); ++s)
    quotedNames_.push_back(nlohmann::json(speciesNames[s]).dump());
  std::string text;
  text.reserve(rows.size() * 240);
  for (const TreeRow& t : rows) {
    // Features one to a line, a comma ending each line but the last.
    text += features_++ == 0 ? "\n" : ",\n";
    fmt::format_to(std::back_inserter(text),
                   "{{\"type\":\"Feature\",\"geometry\":{{\"type\":\"Point\",\"coordinates\":"
                   "[{:.3f},{:.3f},{:.3f}]}},\"properties\":{{\"id\":{},\"species\":{},"
                   "\"age\":{},\"height_m\":{:.3f},\"crown_radius_m\":{:.3f},"
                   "\"crown_base_m\":{:.3f},\"dbh_m\":{:.4f},\"vigor\":{:.3f}}}}}",
                   grid_.originEast_m + t.east_m, grid_.originNorth_m + t.north_m, t.ground_m, t.id,
                   quotedNames_[static_cast<std::size_t>(t.species)], t.age_years, t.height_m,
                   t.crownRadius_m, t.crownBase_m, t.dbh_m, t.vigor);
  }
  out_.write(text);
}

void TreesGeoJsonWriter::commit() {
  out_.write("\n]}\n");
  out_.commit();
}

void writeTreesGeoJson(const std::filesystem::path& file, const TreeSnapshot& snapshot,
                       const Grid& grid) {
  TreesGeoJsonWriter writer(file, grid, snapshot.year);
  writer.write(snapshot.trees, snapshot.speciesNames);
  writer.commit();
}

}  // namespace eco
