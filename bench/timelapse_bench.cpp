// Frames per second of a growth time-lapse of the default run at 640x360 (orbit, years 0 to
// 60), and how the time splits between building the instances (reading snapshots and
// interpolating), rendering (with read-back) and encoding (H.264 through ffmpeg when it is
// installed, else PNG frames).
// Usage: timelapse_bench [SCENARIO = default] [SECONDS = 4] [FPS = 30] [SIZE = 640x360]
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bench_run.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/scene_renderer.hpp"
#include "render/scene/timelapse.hpp"

int main(int argc, char** argv) {
  const std::filesystem::path scenario =
      argc > 1 ? std::filesystem::path(argv[1])
               : std::filesystem::path(ECOFOREST_DATA_DIR) / "default.toml";
  const eco::RunFolder folder = eco::bench::growRun(scenario, "timelapse_bench");
  const std::filesystem::path work = folder.dir.parent_path();
  const eco::Terrain terrain = eco::loadTerrain(folder.scenario);
  const eco::TreeLibrary library(eco::loadLibrarySpecies(folder.scenario), {});
  eco::HeadlessGl gl;
  eco::SceneRenderer renderer(terrain, folder.scenario.climate.latitude_deg, &library);

  eco::TimelapseSettings settings;
  settings.toYear = folder.snapshotYears.back();
  settings.seconds = argc > 2 ? std::atof(argv[2]) : 4.0;
  settings.fps = argc > 3 ? std::atoi(argv[3]) : 30;
  settings.frame = eco::parseFrameSize(argc > 4 ? argv[4] : "640x360").value_or(eco::FrameSize{});
  settings.camera = eco::orbitPath(terrain);
  settings.overlay = true;
  const bool mp4 = eco::programOnPath("ffmpeg");
  auto sink = mp4 ? eco::mp4Sink(work / "growth.mp4", settings.frame, settings.fps)
                  : eco::pngFolderSink(work / "frames");
  const eco::TimelapseTimings t = eco::renderTimelapse(
      folder, library, terrain, eco::frameDrawer(renderer, settings.frame), settings, *sink, {});
  std::printf("%s, growth 0-%d of %s, %dx%d, %d frames into %s\n", eco::glDescription().c_str(),
              folder.snapshotYears.back(), folder.scenario.name.c_str(), settings.frame.width,
              settings.frame.height, t.frames, mp4 ? "H.264 MP4" : "PNG frames");
  std::printf(
      "%.1f frames/s: %.1f s in all; instances %.2f s (%.1f ms a frame), rendering %.2f s "
      "(%.1f ms), encoding %.2f s (%.1f ms)\n",
      t.frames / t.total_s, t.total_s, t.instances_s, 1000.0 * t.instances_s / t.frames, t.render_s,
      1000.0 * t.render_s / t.frames, t.encode_s, 1000.0 * t.encode_s / t.frames);
  std::filesystem::remove_all(work);
  return 0;
}
