// Seconds and bytes of a run's tree snapshot in each format (sim/run/trees_file.hpp): the
// last snapshot of a run (or of a scenario grown for the bench) written as CSV and as
// binary records, and each read back, best of three: whole, and keeping only the trees of
// 10 cm and more (as `stand` and `compare` read them). What a run spends on each snapshot
// year, and what `render`, `view`, `export`, `stand` and `compare` spend opening one.
// Usage: snapshot_bench [RUN_DIR | SCENARIO.toml = valley.toml] [YEARS = the scenario's]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>

#include "bench_run.hpp"
#include "core/stopwatch.hpp"
#include "sim/ecology/stand_measures.hpp"
#include "sim/run/trees_file.hpp"

namespace {

double bestOfThree(const std::function<void()>& work) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const auto start = std::chrono::steady_clock::now();
    work();
    best = std::min(best, eco::millisecondsSince(start) / 1000.0);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path source =
      argc > 1 ? std::filesystem::path(argv[1])
               : std::filesystem::path(ECOFOREST_DATA_DIR) / "valley.toml";
  const eco::RunFolder run =
      source.extension() == ".toml"
          ? eco::bench::growRun(source, "snapshot_bench",
                                argc > 2 ? std::optional<int>(std::atoi(argv[2])) : std::nullopt)
          : eco::openRunFolder(source);
  const int year = run.snapshotYears.back();
  const eco::TreeSnapshot snapshot = eco::readSnapshot(run, year);
  const auto work = std::filesystem::temp_directory_path() / "ecoforest_snapshot_bench";
  std::filesystem::create_directories(work);
  std::printf("%s, year %d: %zu plants\n", run.scenario.name.c_str(), year, snapshot.trees.size());
  std::printf("%-8s %12s %10s %10s %14s %12s %12s\n", "format", "MB", "write s", "read s",
              "read rows/s", "trees read s", "trees kept");
  const eco::TreeFilter measured = [](const eco::TreeRow& tree) {
    return tree.dbh_m >= eco::kMeasuredDbh_m;
  };
  for (const eco::SnapshotFormat format : {eco::SnapshotFormat::Csv, eco::SnapshotFormat::Binary}) {
    const auto file = work / ("year" + std::string(eco::extensionOf(format)));
    const double write = bestOfThree([&] { eco::writeTrees(file, snapshot, format); });
    std::size_t rows = 0;
    const double read = bestOfThree([&] { rows = eco::readTrees(file).trees.size(); });
    std::size_t trees = 0;
    const double readTrees =
        bestOfThree([&] { trees = eco::readTrees(file, measured).trees.size(); });
    std::printf("%-8s %12.1f %10.2f %10.2f %14.0f %12.2f %12zu\n",
                format == eco::SnapshotFormat::Csv ? "csv" : "binary",
                static_cast<double>(std::filesystem::file_size(file)) / 1e6, write, read,
                static_cast<double>(rows) / read, readTrees, trees);
  }
  std::filesystem::remove_all(work);
  return 0;
}
