#include "sim/run/trees_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <functional>
#include <span>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>
#include <glm/geometric.hpp>

#include "core/atomic_file.hpp"
#include "core/binary_io.hpp"
#include "core/csv_text.hpp"
#include "core/error.hpp"
#include "core/mapped_file.hpp"
#include "core/names.hpp"
#include "sim/run/checksummed_output.hpp"
#include "sim/run/first_fault.hpp"

namespace eco {
namespace {

constexpr std::size_t kTreesColumns = 16, kTreesColumnsWithoutSite = 12;

// The binary format: this header, then one fixed-size little-endian record per plant (the
// layout of appendRecord), then the blockChecksum of everything before it.
constexpr std::string_view kBinaryMagic = "ECOFOREST-TREES";
// 2: XXH3 checksum. Version 1, the same layout checksummed by FNV-1a, is still read.
constexpr std::uint32_t kBinaryVersion = 2;
constexpr SealedVersion kReadableVersions[] = {{kBinaryVersion, kWrittenHash},
                                               {1, BlockHash::Fnv1a}};
// id, species, east, north, ground, age, height, crown radius, crown base, dbh, vigor,
// variant seed, the site's four components: the simulation's numbers exactly, so a binary
// snapshot written out as CSV has the bytes of the CSV snapshot.
constexpr std::size_t kRecordBytes = 8 + 2 + 3 * 4 + 4 + 5 * 4 + 4 + 4 * 4;

MappedFile mapped(const std::filesystem::path& file,
                  MappedFile::Reading reading = MappedFile::Reading::Whole) {
  std::optional<MappedFile> mapping = MappedFile::open(file, reading);
  if (!mapping) throw InputError({file.string(), 0, ""}, "cannot read the file");
  return std::move(*mapping);
}

// What makes a parsed row of a trees file unusable (the numbers are finite already), or "".
// No tree is taller than about 120 m or has a crown wider than about 50 m; the limits leave
// room and keep an edited file from making meshes of astronomical size.
std::string treeRowFault(const TreeRow& tree) {
  constexpr float kTallest_m = 200.0f, kWidestCrown_m = 100.0f;
  if (tree.id == 0) return "id 0: ids start at 1";
  if (tree.age_years < 0) return fmt::format("age {} is negative", tree.age_years);
  if (!(tree.height_m >= 0.0f && tree.height_m <= kTallest_m))
    return fmt::format("height {} m is not between 0 and {} m", tree.height_m, kTallest_m);
  if (!(tree.crownRadius_m >= 0.0f && tree.crownRadius_m <= kWidestCrown_m))
    return fmt::format("crown radius {} m is not between 0 and {} m", tree.crownRadius_m,
                       kWidestCrown_m);
  if (!(tree.crownBase_m >= 0.0f && tree.crownBase_m <= tree.height_m))
    return fmt::format("crown base {} m is not between 0 and the height {} m", tree.crownBase_m,
                       tree.height_m);
  if (!(tree.dbh_m >= 0.0f && tree.dbh_m <= 0.05f * kTallest_m))
    return fmt::format("dbh {} m is not between 0 and {} m", tree.dbh_m, 0.05f * kTallest_m);
  if (!(tree.vigor >= 0.0f && tree.vigor <= 1.0f))
    return fmt::format("vigor {} is not between 0 and 1", tree.vigor);
  // Lengths of at most 1, with room for the file's two decimals.
  constexpr float kLongest = 1.01f;
  if (glm::length(tree.site.light) > kLongest)
    return fmt::format("light ({}, {}) is longer than 1", tree.site.light.x, tree.site.light.y);
  if (glm::length(tree.site.wind) > kLongest)
    return fmt::format("wind ({}, {}) is longer than 1", tree.site.wind.x, tree.site.wind.y);
  return {};
}

using RowAt = std::function<TreeRow(std::size_t)>;

// Encodes `count` rows side by side, a chunk of rows to a string, and hands the strings to
// `write` in order, a batch of chunks at a time: a landscape's 100 million rows would
// otherwise be gigabytes in memory at once, and so would their sites, which are worked out
// row by row. While one batch is written out, the next is encoded.
void writeInBatches(std::size_t count, std::size_t bytesPerRow,
                    const std::function<void(std::size_t, std::string&)>& encode,
                    const std::function<void(std::string_view)>& write) {
  constexpr std::size_t kRowsPerChunk = 16384, kChunksPerBatch = 64;
  constexpr std::size_t kRowsPerBatch = kRowsPerChunk * kChunksPerBatch;
  auto encodeBatch = [&](std::size_t first, std::vector<std::string>& chunks) {
    tbb::parallel_for(std::size_t{0}, kChunksPerBatch, [&](std::size_t c) {
      std::string& bytes = chunks[c];
      bytes.clear();
      const std::size_t begin = std::min(count, first + c * kRowsPerChunk);
      const std::size_t end = std::min(count, begin + kRowsPerChunk);
      bytes.reserve((end - begin) * bytesPerRow);
      for (std::size_t i = begin; i < end; ++i) encode(i, bytes);
    });
  };
  std::vector<std::string> ready(kChunksPerBatch), next(kChunksPerBatch);
  encodeBatch(0, ready);
  for (std::size_t first = 0; first < count; first += kRowsPerBatch) {
    tbb::task_group encoding;
    if (first + kRowsPerBatch < count)
      encoding.run([&] { encodeBatch(first + kRowsPerBatch, next); });
    for (const std::string& bytes : ready) write(bytes);
    encoding.wait();
    std::swap(ready, next);
  }
}

// A CSV row; the numbers one by one (appendFixed, appendInteger): fmt's float formatting was
// a tenth of a run.
void appendCsvRow(std::string& text, const TreeRow& row, std::string_view species) {
  auto fixed = [&](double value, int decimals) {
    appendFixed(text, static_cast<float>(value), decimals);
    text += ',';
  };
  auto integer = [&](auto value) {
    appendInteger(text, value);
    text += ',';
  };
  integer(row.id);
  text += species;
  text += ',';
  fixed(row.east_m, 3);
  fixed(row.north_m, 3);
  fixed(row.ground_m, 3);
  integer(row.age_years);
  fixed(row.height_m, 3);
  fixed(row.crownRadius_m, 3);
  fixed(row.crownBase_m, 3);
  fixed(row.dbh_m, 4);
  fixed(row.vigor, 3);
  integer(row.variantSeed);
  fixed(row.site.light.x, 2);
  fixed(row.site.light.y, 2);
  fixed(row.site.wind.x, 2);
  appendFixed(text, row.site.wind.y, 2);
  text += '\n';
}

// The rows without the header.
void writeCsvRows(AtomicFile& out, std::size_t count, const RowAt& rowAt,
                  const std::vector<std::string>& speciesNames) {
  constexpr std::size_t kLongestRow = 120;  // bytes: a tree's row is about 107
  writeInBatches(
      count, kLongestRow,
      [&](std::size_t i, std::string& text) {
        const TreeRow row = rowAt(i);
        appendCsvRow(text, row, speciesNames[static_cast<std::size_t>(row.species)]);
      },
      [&](std::string_view text) { out.write(text); });
}

void writeCsv(AtomicFile& out, std::size_t count, const RowAt& rowAt,
              const std::vector<std::string>& speciesNames) {
  out.write(std::string(kTreesCsvHeader) + "\n");
  writeCsvRows(out, count, rowAt, speciesNames);
}

std::vector<std::string> speciesNamesOf(const Ecosystem& ecosystem) {
  std::vector<std::string> names;
  for (const EcosystemSpecies& s : ecosystem.species()) names.push_back(s.species.name);
  return names;
}

RowAt plantRows(const Ecosystem& ecosystem, const Plants& p) {
  return [&ecosystem, &p](std::size_t i) {
    TreeRow row;
    row.id = p.id[i];
    row.species = p.species[i];
    row.east_m = p.east_m[i];
    row.north_m = p.north_m[i];
    row.ground_m = ecosystem.groundOf(p, i);
    row.age_years = p.age_years[i];
    row.height_m = p.height_m[i];
    row.crownRadius_m = p.crownRadius_m[i];
    row.crownBase_m = p.crownBase_m[i];
    row.dbh_m = p.dbh_m[i];
    row.vigor = p.vigor[i];
    row.variantSeed = ecosystem.variantSeedOf(p.id[i]);
    row.site = ecosystem.siteOf(p, i);
    return row;
  };
}

template <typename T>
void putField(char*& at, T value) {
  std::memcpy(at, &value, sizeof value);
  at += sizeof value;
}

void appendRecord(std::string& bytes, const TreeRow& row) {
  const std::size_t start = bytes.size();
  bytes.resize(start + kRecordBytes);
  char* at = bytes.data() + start;
  putField(at, row.id);
  putField(at, static_cast<std::uint16_t>(row.species));
  putField(at, static_cast<float>(row.east_m));
  putField(at, static_cast<float>(row.north_m));
  putField(at, static_cast<float>(row.ground_m));
  putField(at, static_cast<std::int32_t>(row.age_years));
  for (float value : {row.height_m, row.crownRadius_m, row.crownBase_m, row.dbh_m, row.vigor})
    putField(at, value);
  putField(at, row.variantSeed);
  for (float value : {row.site.light.x, row.site.light.y, row.site.wind.x, row.site.wind.y})
    putField(at, value);
}

// The record at the start of `record` (kRecordBytes of it).
TreeRow recordAt(std::string_view record) {
  BinaryReader r(record);
  TreeRow row;
  row.id = r.get<std::uint64_t>();
  row.species = r.get<std::uint16_t>();
  row.east_m = r.get<float>();
  row.north_m = r.get<float>();
  row.ground_m = r.get<float>();
  row.age_years = r.get<std::int32_t>();
  for (float* value : {&row.height_m, &row.crownRadius_m, &row.crownBase_m, &row.dbh_m, &row.vigor})
    *value = r.get<float>();
  row.variantSeed = r.get<std::uint32_t>();
  for (float* value : {&row.site.light.x, &row.site.light.y, &row.site.wind.x, &row.site.wind.y})
    *value = r.get<float>();
  return row;
}

void writeBinary(AtomicFile& out, std::size_t count, const RowAt& rowAt,
                 const std::vector<std::string>& speciesNames) {
  ECO_ASSERT(speciesNames.size() <= 65535, "species indices of 16 bits");
  ChecksummedOutput body(out);
  BinaryWriter header = sealedHeader(kBinaryMagic, kBinaryVersion);
  header.put(static_cast<std::uint32_t>(speciesNames.size()));
  for (const std::string& name : speciesNames) header.putString(name);
  header.put(static_cast<std::uint64_t>(count));
  body.add(header.bytes());
  writeInBatches(
      count, kRecordBytes,
      [&](std::size_t i, std::string& bytes) { appendRecord(bytes, rowAt(i)); },
      [&](std::string_view bytes) { body.add(bytes); });
  body.finish();
}

// A row of a trees file with `columns` fields (with or without the site's), its species
// field aside; an InputError names the line of a row that is not one.
std::string_view parseTreeRow(std::string_view row, std::size_t columns,
                              const std::filesystem::path& file, int line, TreeRow& tree) {
  std::string_view fields[kTreesColumns];
  const std::size_t count = splitFields(row, std::span(fields, columns));
  bool ok = count == columns && parseField(fields[0], tree.id) &&
            parseField(fields[2], tree.east_m) && parseField(fields[3], tree.north_m) &&
            parseField(fields[4], tree.ground_m) && parseField(fields[5], tree.age_years) &&
            parseField(fields[6], tree.height_m) && parseField(fields[7], tree.crownRadius_m) &&
            parseField(fields[8], tree.crownBase_m) && parseField(fields[9], tree.dbh_m) &&
            parseField(fields[10], tree.vigor) && parseField(fields[11], tree.variantSeed) &&
            !fields[1].empty();
  if (ok && columns == kTreesColumns)
    ok = parseField(fields[12], tree.site.light.x) && parseField(fields[13], tree.site.light.y) &&
         parseField(fields[14], tree.site.wind.x) && parseField(fields[15], tree.site.wind.y);
  std::uint64_t wideSeed = 0;
  if (!ok && count == columns && !parseField(fields[11], tree.variantSeed) &&
      parseField(fields[11], wideSeed))
    throw InputError({file.string(), line, "variant_seed"},
                     "a seed beyond 32 bits, as earlier builds of ecoforest wrote them: run "
                     "the scenario again");
  if (!ok)
    throw InputError(
        {file.string(), line, ""},
        fmt::format("expected {} comma-separated numbers: {}", columns,
                    columns == kTreesColumns ? kTreesCsvHeader : kTreesCsvHeaderWithoutSite));
  return fields[1];
}

// The lines of `text`, the last one with or without its newline; a megabyte to a task.
std::size_t lineCountOf(std::string_view text) {
  const std::size_t newlines = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, text.size(), std::size_t{1} << 20), std::size_t{0},
      [&](const tbb::blocked_range<std::size_t>& range, std::size_t count) {
        return count + static_cast<std::size_t>(std::count(
                           text.begin() + static_cast<std::ptrdiff_t>(range.begin()),
                           text.begin() + static_cast<std::ptrdiff_t>(range.end()), '\n'));
      },
      std::plus<>());
  return newlines + (text.empty() || text.back() == '\n' ? 0 : 1);
}

// A stretch of a trees file's rows, whole lines, read on its own: its trees go to their
// lines' places, their species numbered in the stretch's order of first appearance.
struct TreeChunk {
  std::string_view text;
  int firstLine = 0;
  std::size_t firstSlot = 0;  // the place of its first line among its batch's rows
  std::size_t lines = 0;
  std::vector<std::string> speciesNames;
  std::exception_ptr fault;  // its first bad row: the file's first in the earliest chunk
};

// The chunk's rows into `trees` from its first line's place on, each flagged in `filled`
// (empty lines are not).
void readTreeChunk(TreeChunk& chunk, std::size_t columns, const std::filesystem::path& file,
                   TreeRow* trees, char* filled) {
  try {
    forEachLine(chunk.text, [&](int number, std::string_view row) {
      if (row.empty()) return;
      const int line = chunk.firstLine + number - 1;
      const auto place = static_cast<std::size_t>(number - 1);
      TreeRow& tree = trees[place];
      const std::string_view species = parseTreeRow(row, columns, file, line, tree);
      auto known = std::find(chunk.speciesNames.begin(), chunk.speciesNames.end(), species);
      if (known == chunk.speciesNames.end()) {
        if (const std::string why = whyNotAPlainName(species); !why.empty())
          throw InputError({file.string(), line, ""},
                           fmt::format("species '{}' is not a species name: {}", species, why));
        known = chunk.speciesNames.emplace(known, species);
      }
      if (const std::string fault = treeRowFault(tree); !fault.empty())
        throw InputError({file.string(), line, ""}, fault);
      tree.species = static_cast<int>(known - chunk.speciesNames.begin());
      filled[place] = 1;
    });
  } catch (...) {
    chunk.fault = std::current_exception();
  }
}

void writeRows(AtomicFile& out, SnapshotFormat format, std::size_t count, const RowAt& rowAt,
               const std::vector<std::string>& speciesNames) {
  if (format == SnapshotFormat::Binary)
    writeBinary(out, count, rowAt, speciesNames);
  else
    writeCsv(out, count, rowAt, speciesNames);
}

}  // namespace

std::string_view extensionOf(SnapshotFormat format) {
  return format == SnapshotFormat::Binary ? ".bin" : ".csv";
}

std::optional<SnapshotFormat> snapshotFormatOf(const std::filesystem::path& file) {
  for (SnapshotFormat format : {SnapshotFormat::Csv, SnapshotFormat::Binary})
    if (file.extension() == extensionOf(format)) return format;
  return std::nullopt;
}

void writeTrees(AtomicFile& out, const Ecosystem& ecosystem, const Plants& plants,
                SnapshotFormat format) {
  writeRows(out, format, plants.size(), plantRows(ecosystem, plants), speciesNamesOf(ecosystem));
}

void writeTrees(const std::filesystem::path& file, const Ecosystem& ecosystem, const Plants& plants,
                SnapshotFormat format) {
  AtomicFile out(file);
  writeTrees(out, ecosystem, plants, format);
  out.commit();
}

void writeTrees(const std::filesystem::path& file, const TreeSnapshot& snapshot,
                SnapshotFormat format) {
  AtomicFile out(file);
  writeRows(
      out, format, snapshot.trees.size(), [&](std::size_t i) { return snapshot.trees[i]; },
      snapshot.speciesNames);
  out.commit();
}

namespace {

// How a read goes: the rows it keeps, and whether each batch of them goes to `each` (then
// dropped) instead of into the snapshot. Filtered or batch by batch, neither the file's
// bytes nor its rows are ever held whole: the file is mapped in parts, each released once
// its batch is done.
struct ReadPlan {
  const TreeFilter& keep;
  const TreeBatch* each = nullptr;
  bool inParts() const { return keep || each != nullptr; }
  MappedFile::Reading reading() const {
    return inParts() ? MappedFile::Reading::InParts : MappedFile::Reading::Whole;
  }
  // The batch's rows, from `start` on, handed on and dropped (batch by batch only).
  void handOn(TreeSnapshot& snapshot, std::size_t start) const {
    if (each == nullptr) return;
    (*each)(std::span<const TreeRow>(snapshot.trees).subspan(start), snapshot.speciesNames);
    snapshot.trees.resize(start);
  }
};

TreeSnapshot readCsv(const std::filesystem::path& file, const ReadPlan& plan) {
  const TreeFilter& keep = plan.keep;
  const MappedFile mapping = mapped(file, plan.reading());
  const std::string_view text = mapping.bytes();
  if (text.empty()) throw InputError({file.string(), 0, ""}, "the file is empty");
  const std::size_t headerEnd = std::min(text.find('\n'), text.size());
  const std::string_view header(text.data(), headerEnd);
  std::size_t columns = kTreesColumns;
  if (header == kTreesCsvHeaderWithoutSite)
    columns = kTreesColumnsWithoutSite;
  else if (header != kTreesCsvHeader)
    throw InputError({file.string(), 1, ""},
                     fmt::format("not a trees file: the header must be '{}'", kTreesCsvHeader));

  // The rows, read in stretches of whole lines side by side (a landscape's snapshot holds
  // tens of millions), a batch of stretches at a time, each tree put at its line's place
  // at the end of the snapshot's rows and the ones not kept dropped: the trees, their
  // species' order and the first fault reported are those of reading the lines in order.
  // Read whole, the lines are counted first, for room for all of the rows.
  const std::string_view body = std::string_view(text).substr(std::min(text.size(), headerEnd + 1));
  TreeSnapshot snapshot;
  if (!plan.inParts()) snapshot.trees.reserve(lineCountOf(body));
  constexpr std::size_t kChunkBytes = std::size_t{1} << 20, kChunksPerBatch = 64;
  std::vector<TreeChunk> chunks;
  std::vector<char> filled;
  std::size_t slots = 0;  // the lines of the batches before
  for (std::size_t next = 0; next < body.size();) {
    const std::size_t batchStart = next;
    chunks.clear();
    while (next < body.size() && chunks.size() < kChunksPerBatch) {
      std::size_t end = std::min(body.size(), next + kChunkBytes);
      end = std::min(body.size(), body.find('\n', end - 1) + 1);  // npos + 1 is 0
      if (end <= next) end = body.size();
      chunks.emplace_back().text = body.substr(next, end - next);
      next = end;
    }
    tbb::parallel_for(std::size_t{0}, chunks.size(),
                      [&](std::size_t c) { chunks[c].lines = lineCountOf(chunks[c].text); });
    std::size_t batchLines = 0;
    for (TreeChunk& chunk : chunks) {
      chunk.firstSlot = batchLines;
      chunk.firstLine = static_cast<int>(2 + slots + batchLines);
      batchLines += chunk.lines;
    }
    slots += batchLines;

    const std::size_t start = snapshot.trees.size();
    snapshot.trees.resize(start + batchLines);
    filled.assign(batchLines, 0);
    tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
      readTreeChunk(chunks[c], columns, file, snapshot.trees.data() + start + chunks[c].firstSlot,
                    filled.data() + chunks[c].firstSlot);
    });
    for (const TreeChunk& chunk : chunks)
      if (chunk.fault) std::rethrow_exception(chunk.fault);

    // The species in the file's order of first appearance, and the rows kept without gaps.
    std::size_t kept = start;
    for (const TreeChunk& chunk : chunks) {
      std::vector<int> speciesOf;
      for (const std::string& name : chunk.speciesNames) {
        auto found = std::find(snapshot.speciesNames.begin(), snapshot.speciesNames.end(), name);
        if (found == snapshot.speciesNames.end()) found = snapshot.speciesNames.insert(found, name);
        speciesOf.push_back(static_cast<int>(found - snapshot.speciesNames.begin()));
      }
      for (std::size_t i = chunk.firstSlot; i < chunk.firstSlot + chunk.lines; ++i)
        if (filled[i]) {
          TreeRow& tree = snapshot.trees[kept] = snapshot.trees[start + i];
          tree.species = speciesOf[static_cast<std::size_t>(tree.species)];
          if (!keep || keep(tree)) ++kept;
        }
    }
    snapshot.trees.resize(kept);
    plan.handOn(snapshot, start);
    if (plan.inParts()) mapping.release(body.substr(batchStart, next - batchStart));
  }
  if (keep) snapshot.trees.shrink_to_fit();  // read whole, it holds what it reserved
  return snapshot;
}

TreeSnapshot readBinary(const std::filesystem::path& file, const ReadPlan& plan) {
  const TreeFilter& keep = plan.keep;
  auto refuse = [&](const std::string& why) { return InputError({file.string(), 0, ""}, why); };
  // In parts, the file is gone through twice (its checksum, then its rows), each part
  // released when it is done.
  const MappedFile mapping = mapped(file, plan.reading());
  PartDone release;
  if (plan.inParts()) release = [&](std::string_view part) { mapping.release(part); };
  const std::string_view body = requireSealed(
      mapping.bytes(), kBinaryMagic, kReadableVersions, file,
      {.notOurs = "not a binary trees file of ecoforest",
       .otherVersion =
           "a binary trees file of another version of ecoforest: run the scenario again",
       .corrupt = "the file is corrupt (checksum mismatch)"},
      release);

  BinaryReader r(body);
  TreeSnapshot snapshot;
  const auto speciesCount = r.get<std::uint32_t>();
  for (std::uint32_t s = 0; s < speciesCount && !r.failed(); ++s) {
    std::string name = r.getString();
    if (const std::string why = whyNotAPlainName(name); !why.empty() && !r.failed())
      throw refuse(fmt::format("species '{}' is not a species name: {}", name, why));
    snapshot.speciesNames.push_back(std::move(name));
  }
  const auto count = r.get<std::uint64_t>();
  const std::size_t recordsAt = body.size() - r.remaining();
  if (r.failed() || r.remaining() / kRecordBytes != count || r.remaining() % kRecordBytes != 0)
    throw refuse("the file is corrupt (its length is not that of its rows)");

  auto fault = [&](const TreeRow& tree) -> std::string {
    if (!std::isfinite(tree.east_m) || !std::isfinite(tree.north_m) ||
        !std::isfinite(tree.ground_m))
      return "a position that is not a finite number";
    if (static_cast<std::size_t>(tree.species) >= snapshot.speciesNames.size())
      return fmt::format("species {} of {}", tree.species + 1, snapshot.speciesNames.size());
    return treeRowFault(tree);
  };
  // A batch of rows at a time, decoded at the end of the snapshot's as they are checked,
  // side by side, and the ones not kept dropped.
  if (!plan.inParts()) snapshot.trees.reserve(count);
  constexpr std::uint64_t kRowsPerBatch = std::uint64_t{1} << 20;
  for (std::uint64_t first = 0; first < count; first += kRowsPerBatch) {
    const auto rows = static_cast<std::size_t>(std::min(kRowsPerBatch, count - first));
    const std::size_t start = snapshot.trees.size();
    snapshot.trees.resize(start + rows);
    TreeRow* trees = snapshot.trees.data() + start;
    const std::size_t i = firstFaulty(rows, [&](std::size_t row) {
      trees[row] = recordAt(body.substr(recordsAt + (first + row) * kRecordBytes, kRecordBytes));
      return !fault(trees[row]).empty();
    });
    if (i < rows)
      throw refuse(
          fmt::format("row {} (tree {}): {}", first + i + 1, trees[i].id, fault(trees[i])));
    if (release) release(body.substr(recordsAt + first * kRecordBytes, rows * kRecordBytes));
    if (keep)
      snapshot.trees.erase(
          std::remove_if(snapshot.trees.begin() + static_cast<std::ptrdiff_t>(start),
                         snapshot.trees.end(), [&](const TreeRow& tree) { return !keep(tree); }),
          snapshot.trees.end());
    plan.handOn(snapshot, start);
  }
  if (keep) snapshot.trees.shrink_to_fit();
  return snapshot;
}

TreeSnapshot readByExtension(const std::filesystem::path& file, const ReadPlan& plan) {
  return snapshotFormatOf(file) == SnapshotFormat::Binary ? readBinary(file, plan)
                                                          : readCsv(file, plan);
}

}  // namespace

TreesCsvWriter::TreesCsvWriter(const std::filesystem::path& file) : out_(file) {
  out_.write(std::string(kTreesCsvHeader) + "\n");
}

void TreesCsvWriter::write(std::span<const TreeRow> rows,
                           const std::vector<std::string>& speciesNames) {
  writeCsvRows(
      out_, rows.size(), [&](std::size_t i) { return rows[i]; }, speciesNames);
}

TreeSnapshot readTreesCsv(const std::filesystem::path& file, const TreeFilter& keep) {
  return readCsv(file, {keep});
}

TreeSnapshot readTreesBinary(const std::filesystem::path& file, const TreeFilter& keep) {
  return readBinary(file, {keep});
}

TreeSnapshot readTrees(const std::filesystem::path& file, const TreeFilter& keep) {
  return readByExtension(file, {keep});
}

void readTreesInBatches(const std::filesystem::path& file, const TreeFilter& keep,
                        const TreeBatch& each) {
  readByExtension(file, {keep, &each});
}

std::size_t treeRowsAtMost(const std::filesystem::path& file) {
  const MappedFile mapping = mapped(file, MappedFile::Reading::InParts);
  const std::string_view bytes = mapping.bytes();
  if (snapshotFormatOf(file) == SnapshotFormat::Binary) return bytes.size() / kRecordBytes;
  constexpr std::size_t kPartBytes = std::size_t{64} << 20;
  std::size_t lines = 0;  // the header's among them: each part's last may be cut in two
  for (std::size_t at = 0; at < bytes.size(); at += kPartBytes) {
    const std::string_view part = bytes.substr(at, kPartBytes);
    lines += lineCountOf(part);
    mapping.release(part);
  }
  return lines;
}

}  // namespace eco
