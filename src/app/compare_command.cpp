#include "app/compare_command.hpp"

#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "app/render_command.hpp"
#include "app/scene_source.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "sim/image_io.hpp"
#include "sim/plan/plan_spec.hpp"
#include "sim/run/charts.hpp"
#include "sim/run/comparison.hpp"
#include "sim/run/simulation.hpp"
#include "sim/run/stand_table.hpp"

namespace eco {
namespace {

struct CompareArgs {
  std::vector<std::string> runs;
  std::string out;
  std::vector<int> years;
  std::string region;  // TOML keys of a plan's region
  bool noStills = false;
  ViewOptions view;
};

// A measure charted over the years.
struct Charted {
  const char* file;
  const char* title;
  const char* unit;
  double (*of)(const StandYear&);
};

const Charted kCharts[] = {
    {"basal_area.png", "Basal area (trees of at least 10 cm)", "m²/ha",
     [](const StandYear& y) { return y.stand.basalArea_m2PerHa; }},
    {"stems_per_ha.png", "Stems (at least 10 cm)", "stems/ha",
     [](const StandYear& y) { return y.stand.stemsPerHa; }},
    {"dominant_height.png", "Dominant height (100 tallest per ha)", "m",
     [](const StandYear& y) { return y.stand.dominantHeight_m; }},
    {"canopy_cover.png", "Canopy cover", "% of the map",
     [](const StandYear& y) { return 100.0 * y.stand.coverFraction; }},
    {"volume.png", "Standing stem volume", "m³/ha",
     [](const StandYear& y) { return y.stand.volume_m3PerHa; }},
    {"removed_volume.png", "Stem volume removed by thinning, so far", "m³/ha",
     [](const StandYear& y) { return y.removedVolumeSoFar_m3PerHa; }},
};

// Diameter classes of the compared stand tables, cm.
constexpr double kCompareClassWidth_cm = 5.0;

// Each run's stand table in each year every run has a snapshot of, of the whole map or
// within a region: a CSV of them all (stand_tables.csv, the run's name first on each line),
// a chart of the stems per class for each year, and each run's species' and stand's
// measures in each year (stand_measures.csv).
void writeDiameterDistributions(const std::vector<RunFolder>& folders,
                                const std::vector<std::string>& names,
                                const std::vector<int>& years,
                                const std::optional<RegionSpec>& region,
                                const std::filesystem::path& out) {
  // tables[run][k]: the map and species files of each run read once for all its years.
  std::vector<std::vector<StandTable>> tables;
  for (const RunFolder& folder : folders)
    tables.push_back(standTablesOfRun(folder, years, kCompareClassWidth_cm, region));
  std::string csv = fmt::format("run,{}\n", kStandTableCsvHeader);
  std::string measures = fmt::format("run,{}\n", kStandMeasuresCsvHeader);
  for (std::size_t k = 0; k < years.size(); ++k) {
    LineChart chart{fmt::format("Diameter distribution in year {}{} (classes of {:g} cm)", years[k],
                                region ? " within the region" : "", kCompareClassWidth_cm),
                    "dbh, cm (class middle)",
                    "stems/ha",
                    {},
                    {}};
    for (std::size_t i = 0; i < folders.size(); ++i) {
      const StandTable& table = tables[i][k];
      csv += standTableCsvLines(table, names[i] + ",");
      measures += standMeasuresCsvLines(table, names[i] + ",");
      ChartSeries& series = chart.series.emplace_back(ChartSeries{names[i], {}});
      const std::size_t stand = table.rows.size() - 1;
      for (std::size_t c = 0; c < table.classCount(); ++c)
        series.points.emplace_back(table.from_cm(c) + 0.5 * kCompareClassWidth_cm,
                                   table.classes[stand][c].stemsPerHa);
    }
    writeRgb8Image(out / fmt::format("diameters_year_{:04d}.png", years[k]), drawLineChart(chart));
  }
  for (const auto& [name, text] :
       {std::pair{"stand_tables.csv", &csv}, std::pair{"stand_measures.csv", &measures}}) {
    AtomicFile file(out / name);
    file.write(*text);
    file.commit();
  }
}

// Each run by its scenario's name, or its folder's where two runs share a scenario name.
std::vector<std::string> namesOf(const std::vector<RunFolder>& runs) {
  std::vector<std::string> names;
  for (const RunFolder& r : runs) names.push_back(r.scenario.name);
  for (std::size_t i = 0; i < runs.size(); ++i)
    if (std::count(names.begin(), names.end(), runs[i].scenario.name) > 1)
      names[i] = runs[i].dir.filename().string();
  return names;
}

void runCompare(const CompareArgs& args) {
  if (args.runs.size() < 2)
    throw InputError({"compare", 0, ""}, "name at least two run folders to compare");
  std::vector<RunFolder> folders;
  for (const std::string& run : args.runs) folders.push_back(openRunArgument(run));
  std::optional<RegionSpec> region;
  if (!args.region.empty())
    region = parseRegionOption(args.region, "--region", std::filesystem::current_path());
  const std::vector<std::string> names = namesOf(folders);
  std::vector<ComparedRun> runs;
  for (std::size_t i = 0; i < folders.size(); ++i)
    runs.push_back(readComparedRun(folders[i].dir, names[i]));
  const std::vector<int> years = comparisonYears(runs, args.years);
  // Stills and diameter distributions need a snapshot of the year in every run.
  std::vector<int> snapshotYears;
  for (int year : years) {
    const bool everyRun = std::all_of(folders.begin(), folders.end(), [&](const RunFolder& f) {
      return std::binary_search(f.snapshotYears.begin(), f.snapshotYears.end(), year);
    });
    if (everyRun)
      snapshotYears.push_back(year);
    else
      std::cerr << fmt::format(
          "compare: no still or diameter distribution of year {}: not every run has its "
          "snapshot\n",
          year);
  }
  const std::filesystem::path out(args.out);
  createOutputFolder(out);

  auto writeText = [](const std::filesystem::path& file, const std::string& text) {
    AtomicFile f(file);
    f.write(text);
    f.commit();
  };
  writeText(out / "compare.csv", comparisonCsv(runs, years));
  writeText(out / "compare.md", comparisonMarkdown(runs, years));
  for (const Charted& c : kCharts) {
    LineChart chart{c.title, "year", c.unit, {}, {}};
    for (int year : years) chart.markedX.push_back(year);
    for (const ComparedRun& run : runs) {
      ChartSeries& series = chart.series.emplace_back(ChartSeries{run.name, {}});
      for (const StandYear& y : run.years) series.points.emplace_back(y.year, c.of(y));
    }
    writeRgb8Image(out / c.file, drawLineChart(chart));
  }
  writeDiameterDistributions(folders, names, snapshotYears, region, out);
  std::cout << fmt::format(
      "compare: {} runs at years {}: {}/compare.csv, compare.md, {} charts, stand_tables.csv, "
      "stand_measures.csv and {} diameter distributions{}\n",
      runs.size(), fmt::join(years, ", "), out.string(), std::size(kCharts), snapshotYears.size(),
      region ? " within the region" : "");
  if (args.noStills || snapshotYears.empty()) return;
  // One still per run and year; runs whose species are the same files share one tree
  // library, built once (it is the slow and large part).
  std::vector<std::vector<Image>> stills(snapshotYears.size());
  std::unique_ptr<TreeLibrary> library;
  std::uint64_t librarySpecies = 0;
  for (std::size_t i = 0; i < folders.size(); ++i) {
    SceneSource source = sceneSourceOf(folders[i]);
    const std::uint64_t species = speciesFilesFingerprint(source.scenario);
    if (library && species == librarySpecies) {
      source.library = std::move(library);
    } else {
      library.reset();
      std::cout << fmt::format("compare: building the trees of {}\n", folders[i].dir.string())
                << std::flush;
      source.buildLibrary();
      librarySpecies = species;
    }
    const Camera camera = cameraFrom(args.view, source.terrain);
    std::optional<Field> overlay;
    if (!args.view.overlay.empty()) overlay = source.overlay(args.view.overlay);
    for (std::size_t k = 0; k < snapshotYears.size(); ++k)
      stills[k].push_back(drawStill(source,
                                    stillTrees(source, snapshotYears[k], 0, camera, args.view),
                                    camera, args.view, overlay));
    library = std::move(source.library);
  }
  for (std::size_t k = 0; k < snapshotYears.size(); ++k) {
    std::vector<std::string> captions;
    for (const std::string& name : names)
      captions.push_back(fmt::format("{}, year {}", name, snapshotYears[k]));
    const std::filesystem::path file =
        out / fmt::format("stills_year_{:04d}.png", snapshotYears[k]);
    writeRgb8Image(file, sideBySide(stills[k], captions));
    std::cout << fmt::format("compare: {}\n", file.string()) << std::flush;
  }
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  args->view.size = {640, 360};
  CLI::App* command = app.add_subcommand("compare",
                                         "Compare runs: a table at chosen years, charts over time, "
                                         "diameter distributions, stills side by side");
  command->add_option("runs", args->runs, "Two or more run folders of `ecoforest run`")->required();
  command->add_option("--out", args->out, "Folder to write the comparison into")->required();
  command
      ->add_option("--years", args->years,
                   "Years to compare, e.g. 30,60,100 (default: those of 30, 60, 100 every run "
                   "reaches)")
      ->delimiter(',');
  command->add_option("--region", args->region,
                      "Stand tables, measures and diameter distributions within a region, "
                      "given as a plan's rule gives it: 'polygon = [[x, y], ...]' in map "
                      "metres, or a line or mask, with buffer_m (docs/planning.md)");
  command->add_flag("--no-stills", args->noStills, "Write the table and charts only");
  addFrameOptions(*command, args->view);
  addCameraOptions(*command, args->view);
  command->callback([args] { runCompare(*args); });
}

}  // namespace eco
