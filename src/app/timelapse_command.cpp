#include "app/timelapse_command.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "app/scene_source.hpp"
#include "app/view_options.hpp"
#include "core/error.hpp"
#include "core/progress.hpp"
#include "render/gl/gl_context.hpp"
#include "render/scene/timelapse.hpp"

namespace eco {
namespace {

struct TimelapseArgs {
  std::string run;
  std::string kind = "growth";
  std::string years;
  double seconds = 10.0;
  int fps = 30;
  std::string cameraPath = "orbit";
  std::string out;
  bool overlay = false;
  bool ignoreMemoryCheck = false;
  ViewOptions view;
};

// "A:B" (growth) or "A" (wind); nullopt when malformed.
std::optional<std::pair<double, double>> parseYears(const std::string& text) {
  double a = 0.0, b = 0.0;
  char colon = 0, rest = 0;
  const int n = std::sscanf(text.c_str(), "%lf%c%lf%c", &a, &colon, &b, &rest);
  if (n == 1) return std::make_pair(a, a);
  if (n == 3 && colon == ':') return std::make_pair(a, b);
  return std::nullopt;
}

void runTimelapse(const TimelapseArgs& args) {
  std::filesystem::path out(args.out);
  if (!out.has_filename()) out = out.parent_path();  // "frames/" is the folder "frames"
  const bool mp4 = out.extension() == ".mp4";
  if (!mp4 && out.has_extension())
    throw InputError({args.out, 0, "--out"}, "write FILE.mp4, or a folder for PNG frames");
  requireOutputFolder(out);
  SceneSource source = openRunSource(args.run);
  const RunFolder& run = *source.run;
  if (run.snapshotYears.empty())
    throw InputError({args.run, 0, ""}, "the run has no snapshots yet");
  TimelapseSettings settings;
  settings.kind = args.kind == "wind" ? TimelapseKind::Wind : TimelapseKind::Growth;
  const int last = run.snapshotYears.back();
  std::pair<double, double> years{settings.kind == TimelapseKind::Growth ? 0.0 : last, last};
  if (!args.years.empty()) {
    const auto parsed = parseYears(args.years);
    if (!parsed)
      throw InputError({"--years", 0, ""},
                       "expected A:B (growth) or A (wind), got '" + args.years + "'");
    years = *parsed;
  }
  if (settings.kind == TimelapseKind::Wind) {
    if (years.first != years.second)
      throw InputError({"--years", 0, ""}, "a wind time-lapse shows one year");
    source.requireSnapshot(static_cast<int>(years.first));
  } else if (years.first < 0.0 || years.second > last || years.first >= years.second) {
    throw InputError(
        {"--years", 0, ""},
        fmt::format("growth years must satisfy 0 <= A < B <= {} (the run's last snapshot)", last));
  }
  settings.fromYear = years.first;
  settings.toYear = years.second;
  settings.seconds = args.seconds;
  settings.fps = args.fps;
  settings.frame = args.view.size;
  settings.overlay = args.overlay;
  settings.ignoreMemoryCheck = args.ignoreMemoryCheck;
  settings.render = renderOptionsFrom(args.view, source.scenario);
  if (args.cameraPath == "orbit")
    settings.camera = orbitPath(source.terrain);
  else if (args.cameraPath == "flyover")
    settings.camera = flyoverPath(source.terrain);
  else
    settings.camera = loadCameraPath(args.cameraPath, source.terrain);

  std::unique_ptr<FrameSink> sink =
      mp4 ? mp4Sink(out, settings.frame, settings.fps) : pngFolderSink(out);
  source.buildLibrary(LibrarySettings::shaped(!args.view.noShaping));
  HeadlessGl gl;
  const std::unique_ptr<SceneRenderer> renderer = sceneRendererFor(source, args.view);
  const bool terminal = Progress::stderrIsTerminal();
  const auto start = std::chrono::steady_clock::now();
  const TimelapseTimings t = renderTimelapse(
      run, *source.library, source.terrain,
      frameDrawer(*renderer, settings.frame, args.view.antialias), settings, *sink,
      [&](int done, int frames) {
        if (!terminal) return;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double rate = done / std::max(elapsed, 1e-6);
        std::fprintf(stderr, "\rtimelapse: frame %d/%d, %.1f frames/s, %.0f s left   ", done,
                     frames, rate, (frames - done) / rate);
        if (done == frames) std::fputc('\n', stderr);
      });
  std::cout << fmt::format(
      "{}: {} frames of {}x{} at {} fps in {:.1f} s ({:.1f} frames/s; instances {:.1f} s, "
      "rendering {:.1f} s, encoding {:.1f} s)\n",
      args.out, t.frames, settings.frame.width, settings.frame.height, settings.fps, t.total_s,
      t.frames / t.total_s, t.instances_s, t.render_s, t.encode_s);
}

}  // namespace

void addTimelapseCommand(CLI::App& app) {
  auto args = std::make_shared<TimelapseArgs>();
  CLI::App* c =
      app.add_subcommand("timelapse", "Render a run's growth or its wind as MP4 or PNG frames");
  c->add_option("run", args->run, "A run folder of `ecoforest run`")->required();
  c->add_option("--kind", args->kind, "growth (years pass) or wind (one year, the wind moves)")
      ->check(CLI::IsMember({"growth", "wind"}));
  c->add_option("--years", args->years,
                "A:B for growth (default 0:last snapshot), A for wind (default the last)");
  c->add_option("--seconds", args->seconds, "Length of the animation")
      ->check(CLI::Range(0.04, 3600.0));
  c->add_option("--fps", args->fps, "Frames per second")->check(CLI::Range(1, 120));
  c->add_option("--camera-path", args->cameraPath, "orbit, flyover or a keyframe FILE.toml");
  c->add_option("--out", args->out, "FILE.mp4, or a folder for numbered PNG frames")->required();
  c->add_flag("--overlay", args->overlay, "Draw the year and a scale bar");
  c->add_flag("--ignore-memory-check", args->ignoreMemoryCheck,
              "Go ahead where two snapshots' trees seem too many for the memory available");
  addFrameOptions(*c, args->view);
  c->callback([args] { runTimelapse(*args); });
}

}  // namespace eco
