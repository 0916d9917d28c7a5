// A run's tree snapshots (trees/year_NNNN.csv or .bin, docs/run_folder.md), each writer
// beside its reader: one row per plant, where it stands, its size and its site. CSV for
// any tool; binary records (the simulation's numbers exactly, in about two thirds of the
// bytes, written and read without formatting numbers) for landscapes of tens of millions of
// plants.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/atomic_file.hpp"
#include "sim/ecology/ecosystem.hpp"
#include "sim/ecology/plant_site.hpp"
#include "sim/scenario.hpp"

namespace eco {

// The file extension of a format (".csv", ".bin"), and the format a file's extension names.
std::string_view extensionOf(SnapshotFormat format);
std::optional<SnapshotFormat> snapshotFormatOf(const std::filesystem::path& file);

// A CSV snapshot's header. The last four columns are the plant's site as it shapes the tree
// (plant_site.hpp): toward the light and toward where the wind blows, east and north, each
// of length 0..1.
inline constexpr const char* kTreesCsvHeader =
    "id,species,x_m,y_m,z_m,age,height_m,crown_radius_m,crown_base_m,dbh_m,vigor,variant_seed,"
    "light_east,light_north,wind_east,wind_north";
// Snapshots of earlier versions, without the site: they read as unshaped trees.
inline constexpr const char* kTreesCsvHeaderWithoutSite =
    "id,species,x_m,y_m,z_m,age,height_m,crown_radius_m,crown_base_m,dbh_m,vigor,variant_seed";

struct TreeRow {
  std::uint64_t id = 0;
  int species = 0;  // index into TreeSnapshot::speciesNames
  double east_m = 0.0, north_m = 0.0, ground_m = 0.0;
  int age_years = 0;
  float height_m = 0.0f, crownRadius_m = 0.0f, crownBase_m = 0.0f, dbh_m = 0.0f, vigor = 0.0f;
  std::uint32_t variantSeed = 0;
  PlantSite site;
};

struct TreeSnapshot {
  int year = 0;
  std::vector<std::string> speciesNames;  // in order of first appearance
  std::vector<TreeRow> trees;
};

// Plants of the ecosystem's map and species: its plants after a step, with their sites
// under this year's canopy, or the trees a thinning removed.
void writeTrees(const std::filesystem::path& file, const Ecosystem& ecosystem, const Plants& plants,
                SnapshotFormat format);
// The same into `out`, which the caller commits (a run, in the background).
void writeTrees(AtomicFile& out, const Ecosystem& ecosystem, const Plants& plants,
                SnapshotFormat format);
// A snapshot read back, in either format.
void writeTrees(const std::filesystem::path& file, const TreeSnapshot& snapshot,
                SnapshotFormat format);
// A CSV snapshot written a batch of rows at a time (`export` writes a binary snapshot read
// in batches as CSV): the header, then each batch's rows, whose species number the names.
class TreesCsvWriter {
 public:
  explicit TreesCsvWriter(const std::filesystem::path& file);
  void write(std::span<const TreeRow> rows, const std::vector<std::string>& speciesNames);
  void commit() { out_.commit(); }

 private:
  AtomicFile out_;
};

// The rows a reader keeps, asked of each row in the file's order (its species numbered as
// in the snapshot); none keeps every row. A stand table needs a landscape's trees of 10
// cm and more, a tenth of its plants: the others are checked but not held beyond their
// batch of rows, nor the file's bytes beyond their batch, so the memory is that of the
// rows kept.
using TreeFilter = std::function<bool(const TreeRow&)>;

// Each reader checks the file as untrusted input: an InputError names the file and the
// line (CSV) or row (binary) at fault. The species names are those of every row, kept or
// not, in the file's order.
TreeSnapshot readTreesCsv(const std::filesystem::path& file, const TreeFilter& keep = {});
TreeSnapshot readTreesBinary(const std::filesystem::path& file, const TreeFilter& keep = {});
// By the file's extension.
TreeSnapshot readTrees(const std::filesystem::path& file, const TreeFilter& keep = {});

// Each batch of a file's rows (those `keep` keeps, in the file's order) as it is read, with
// the species names so far, which its rows' species number: a reader that writes them out
// (`export`) never holds the file or its rows whole. The same checks, faults and numbers as
// readTrees.
using TreeBatch =
    std::function<void(std::span<const TreeRow> rows, const std::vector<std::string>& species)>;
void readTreesInBatches(const std::filesystem::path& file, const TreeFilter& keep,
                        const TreeBatch& each);

// At least as many as the rows the file holds, never more than its size allows: room for a
// reader that keeps every row a batch at a time (a binary file's length over a record's,
// a CSV file's lines, counted a part of the file at a time). Nothing is checked here.
std::size_t treeRowsAtMost(const std::filesystem::path& file);

}  // namespace eco
