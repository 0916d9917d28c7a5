#include "app/compare_command.hpp"

#include <iostream>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "app/render_command.hpp"
#include "app/scene_source.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "sim/image_io.hpp"
#include "sim/run/charts.hpp"
#include "sim/run/comparison.hpp"

namespace eco {
namespace {

struct CompareArgs {
  std::vector<std::string> runs;
  std::string out;
  std::vector<int> years;
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
     [](const StandYear& y) { return y.basalArea_m2PerHa; }},
    {"stems_per_ha.png", "Stems (at least 10 cm)", "stems/ha",
     [](const StandYear& y) { return y.stemsPerHa; }},
    {"dominant_height.png", "Dominant height (100 tallest per ha)", "m",
     [](const StandYear& y) { return y.dominantHeight_m; }},
    {"canopy_cover.png", "Canopy cover", "% of the map",
     [](const StandYear& y) { return 100.0 * y.coverFraction; }},
    {"volume.png", "Standing stem volume", "m³/ha",
     [](const StandYear& y) { return y.volume_m3PerHa; }},
    {"removed_volume.png", "Stem volume removed by thinning, so far", "m³/ha",
     [](const StandYear& y) { return y.removedVolumeSoFar_m3PerHa; }},
};

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
  for (const std::string& run : args.runs) {
    if (!std::filesystem::is_directory(run))
      throw InputError({run, 0, ""}, "no such run folder (make one with `ecoforest run`)");
    folders.push_back(openRunFolder(run));
  }
  const std::vector<std::string> names = namesOf(folders);
  std::vector<ComparedRun> runs;
  for (std::size_t i = 0; i < folders.size(); ++i)
    runs.push_back(readComparedRun(folders[i].dir, names[i]));
  const std::vector<int> years = comparisonYears(runs, args.years);
  // Stills need a snapshot of the year in every run.
  std::vector<int> stillYears;
  for (int year : args.noStills ? std::vector<int>{} : years) {
    const bool everyRun = std::all_of(folders.begin(), folders.end(), [&](const RunFolder& f) {
      return std::binary_search(f.snapshotYears.begin(), f.snapshotYears.end(), year);
    });
    if (everyRun)
      stillYears.push_back(year);
    else
      std::cerr << fmt::format("compare: no still of year {}: not every run has its snapshot\n",
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
  std::cout << fmt::format(
      "compare: {} runs at years {}: {}/compare.csv, compare.md and {} charts\n", runs.size(),
      fmt::join(years, ", "), out.string(), std::size(kCharts));
  if (stillYears.empty()) return;
  std::vector<SceneSource> sources;
  for (const RunFolder& f : folders) {
    std::cout << fmt::format("compare: building the trees of {}\n", f.dir.string()) << std::flush;
    SceneSource& source = sources.emplace_back(openSceneSource(f.dir.string()));
    source.buildLibrary();
  }
  for (int year : stillYears) {
    std::vector<Image> stills;
    std::vector<std::string> captions;
    for (std::size_t i = 0; i < sources.size(); ++i) {
      const Camera camera = cameraFrom(args.view, sources[i].terrain);
      std::optional<Field> overlay;
      if (!args.view.overlay.empty()) overlay = sources[i].overlay(args.view.overlay);
      stills.push_back(
          drawStill(sources[i], sources[i].forestOf(year, 0), camera, args.view, overlay));
      captions.push_back(fmt::format("{}, year {}", names[i], year));
    }
    const std::filesystem::path file = out / fmt::format("stills_year_{:04d}.png", year);
    writeRgb8Image(file, sideBySide(stills, captions));
    std::cout << fmt::format("compare: {}\n", file.string()) << std::flush;
  }
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  args->view.size = {640, 360};
  CLI::App* command = app.add_subcommand(
      "compare", "Compare runs: a table at chosen years, charts over time, stills side by side");
  command->add_option("runs", args->runs, "Two or more run folders of `ecoforest run`")->required();
  command->add_option("--out", args->out, "Folder to write the comparison into")->required();
  command
      ->add_option("--years", args->years,
                   "Years to compare, e.g. 30,60,100 (default: those of 30, 60, 100 every run "
                   "reaches)")
      ->delimiter(',');
  command->add_flag("--no-stills", args->noStills, "Write the table and charts only");
  addFrameOptions(*command, args->view);
  addCameraOptions(*command, args->view);
  command->callback([args] { runCompare(*args); });
}

}  // namespace eco
