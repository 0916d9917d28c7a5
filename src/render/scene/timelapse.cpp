#include "render/scene/timelapse.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>
#include <glm/trigonometric.hpp>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/growth_timeline.hpp"
#include "render/scene/seen_forest.hpp"
#include "render/scene/tree_clearance.hpp"

namespace eco {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Whether a snapshot's rows, read whole, would take at most a quarter of the memory the
// machine has available: a valley's few hundred megabytes do, a landscape's gigabytes not.
bool fitsWhole(const SnapshotRows& rows) {
  return rows.rowsAtMost * sizeof(TreeRow) <= availableMemoryBytes().value_or(0) / 4;
}

// A growth frame's trees are made this many of the interval's at a time: a landscape's
// frame of a hundred million trees is never held whole.
constexpr std::size_t kFramePart = std::size_t{1} << 20;

// Whether tree i of `forest` can matter to a frame whose path sets the camera `path`, which
// clearOfTrees may lift by up to kMaxLift_m: near enough to the eye's column to lift it, or
// drawn (or casting a shadow) from a camera that much nearer than `path`. The renderer draws
// nothing of the others: only the floor shows their crowns.
bool mayMatter(const Forest& forest, std::size_t i, const TreeLibrary& library, const Camera& path,
               float pixelsPerRadian, const LodSettings& lod) {
  const glm::vec3 stem = forest.position[i];
  if (std::hypot(stem.x - path.position.x, stem.z - path.position.z) <=
      drawnReach_m(forest, i, library) + kGroundClearance_m)
    return true;
  return mayBeDrawn(forest, i, library.type(forest.type[i]), path.position, pixelsPerRadian, lod,
                    kMaxLift_m);
}

// The trees of the interval's frame at `year` that can matter to it (mayMatter), made a part
// at a time, with the floor of all of them.
SeenForest frameTrees(const GrowthInterval& interval, double year, const TreeLibrary& library,
                      const Grid& grid, const Camera& path, const FrameSize& frame,
                      const LodSettings& lod) {
  const float pixelsPerRadian = path.pixelsPerRadian(frame.height);
  SeenForestSum sum(library, grid);
  for (std::size_t first = 0; first < interval.size(); first += kFramePart) {
    const Forest part =
        interval.forestAt(year, first, std::min(first + kFramePart, interval.size()));
    sum.add(part, [&](std::size_t i) {
      return mayMatter(part, i, library, path, pixelsPerRadian, lod) ? TreeSeen::Shown
                                                                     : TreeSeen::TooSmall;
    });
  }
  return std::move(sum).done();
}

}  // namespace

int TimelapseSettings::frameCount() const {
  return std::max(1, static_cast<int>(std::lround(seconds * fps)));
}

double TimelapseSettings::yearOfFrame(int frame) const {
  const int frames = frameCount();
  if (kind == TimelapseKind::Wind || frames == 1) return fromYear;
  return fromYear + (toYear - fromYear) * frame / (frames - 1);
}

double metresPerPixelAtCentre(const Camera& camera, const Terrain& terrain, int height) {
  double distance = 1000.0;
  const glm::vec3 d = camera.forward();
  for (double t = 1.0; t < 20000.0; t += std::max(1.0, 0.01 * t)) {
    const glm::vec3 p = camera.position + static_cast<float>(t) * d;
    if (p.y <= groundBelow(terrain, p)) {
      distance = t;
      break;
    }
  }
  return 2.0 * distance * std::tan(0.5 * radians(camera.fovY_deg)) / height;
}

void drawOverlay(Image& frame, double year, double metresPerPixel) {
  OIIO::ImageBuf buffer(OIIO::ImageSpec(frame.width, frame.height, 4, OIIO::TypeDesc::UINT8),
                        frame.rgba.data());
  const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  const float shadow[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  const int size = std::max(14, frame.height / 24);
  const std::string label = fmt::format("year {:.0f}", std::floor(year + 1e-6));
  // DejaVu Sans from fonts-dejavu-core; a missing font leaves the bar without labels.
  OIIO::ImageBufAlgo::render_text(buffer, 13, 11 + size, label, size, "DejaVuSans", shadow);
  OIIO::ImageBufAlgo::render_text(buffer, 12, 10 + size, label, size, "DejaVuSans", white);
  // A bar of a round length (1, 2 or 5 times a power of ten) near a fifth of the width.
  const double target = 0.2 * frame.width * metresPerPixel;
  const double power = std::pow(10.0, std::floor(std::log10(target)));
  double length = power;
  for (double m : {2.0, 5.0})
    if (m * power <= target) length = m * power;
  const int pixels = static_cast<int>(std::lround(length / metresPerPixel));
  const int x0 = 12, y0 = frame.height - 14;
  OIIO::ImageBufAlgo::fill(buffer, shadow, OIIO::ROI(x0 - 1, x0 + pixels + 1, y0 - 5, y0 + 2));
  OIIO::ImageBufAlgo::fill(buffer, white, OIIO::ROI(x0, x0 + pixels, y0 - 4, y0 + 1));
  const std::string text =
      length >= 1000.0 ? fmt::format("{:g} km", length / 1000.0) : fmt::format("{:g} m", length);
  OIIO::ImageBufAlgo::render_text(buffer, x0 + pixels + 8, y0 + 1, text, size * 3 / 4, "DejaVuSans",
                                  white);
  buffer.geterror();
}

TimelapseTimings renderTimelapse(const RunFolder& run, const TreeLibrary& library,
                                 const Terrain& terrain, const DrawFrame& draw,
                                 const TimelapseSettings& settings, FrameSink& sink,
                                 const std::function<void(int, int)>& progress) {
  const auto start = Clock::now();
  TimelapseTimings timings;
  const int frames = settings.frameCount();
  std::vector<int> years{0};  // year 0: the bare landscape before the first snapshot
  years.insert(years.end(), run.snapshotYears.begin(), run.snapshotYears.end());
  Forest forest;
  std::optional<CanopyFloor> floor;        // of every tree of the frame, `forest`'s and not
  std::optional<TreeClearance> clearance;  // of `forest`, made again whenever it changes
  std::optional<ForestIndex> index;        // of `forest` where it is the same in every frame
  // The snapshots around the frames' years, their trees paired once for all their frames.
  std::optional<GrowthInterval> interval;
  int intervalEnd = -1;  // the later snapshot's year of `interval`
  // The later snapshot of an interval is the earlier one of the next: kept where it fits
  // whole, read again a batch at a time where it does not.
  std::optional<TreeSnapshot> kept;
  for (int frame = 0; frame < frames; ++frame) {
    auto phase = Clock::now();
    const double year = settings.yearOfFrame(frame);
    const double u = frames > 1 ? static_cast<double>(frame) / (frames - 1) : 0.0;
    const Camera path = settings.camera(u);  // where the path sets the camera this frame
    RenderOptions options = settings.render;
    if (settings.kind == TimelapseKind::Wind) {
      options.wind.time += frame * settings.windRadiansPerSecond / settings.fps;
      if (frame == 0) {  // one year's trees, built as the snapshot is read (year 0 bare)
        if (const int shown = static_cast<int>(year); shown > 0)
          forest = forestFromRun(run, shown, library);
        floor = canopyFloor(forest, library, terrain.grid);
        clearance.emplace(forest, library);
        index.emplace(forest, library);
      }
    } else {
      // The snapshots around the year (the last pair at the end of the run).
      std::size_t after = 1;
      while (after + 1 < years.size() && years[after] < year) ++after;
      // A landscape's frame holds gigabytes: the last one goes before the next is made.
      clearance.reset();
      floor.reset();
      forest = Forest();
      if (years[after] != intervalEnd) {
        interval.reset();
        const int from = years[after - 1], to = years[after];
        // Their rows counted once (a CSV file's lines are counted through the file).
        const SnapshotRows earlierRows =
            kept && kept->year == from ? SnapshotRows::of(*kept) : SnapshotRows::of(run, from);
        SnapshotRows laterRows = SnapshotRows::of(run, to);
        // A landscape's interval takes gigabytes: refused before the pairing where they are
        // not there, rather than the command killed for want of memory partway.
        requireMemory(
            GrowthInterval::peakBytes(earlierRows.rowsAtMost, laterRows.rowsAtMost),
            fmt::format("the growth between the snapshots of years {} and {} ({} and {} plants)",
                        from, to, earlierRows.rowsAtMost, laterRows.rowsAtMost),
            "Choose other years (--years), or --ignore-memory-check to go ahead anyway.",
            settings.ignoreMemoryCheck);
        std::optional<TreeSnapshot> later;
        if (fitsWhole(laterRows)) {
          later = readSnapshot(run, to);
          laterRows = SnapshotRows::of(*later);
        }
        interval.emplace(earlierRows, laterRows, library, run.dir.string());
        kept = std::move(later);
        intervalEnd = to;
      }
      SeenForest seen =
          frameTrees(*interval, year, library, terrain.grid, path, settings.frame, options.lod);
      forest = std::move(seen.shown);
      floor = std::move(seen.floor);
      clearance.emplace(forest, library);
    }
    timings.instances_s += secondsSince(phase);

    phase = Clock::now();
    // Out of the crowns of this frame's trees, wherever the path was set.
    const Camera camera = clearOfTrees(path, *clearance);
    Image image = draw({forest, *floor, index ? &*index : nullptr}, camera, options);
    timings.render_s += secondsSince(phase);

    phase = Clock::now();
    if (settings.overlay)
      drawOverlay(image, year, metresPerPixelAtCentre(camera, terrain, settings.frame.height));
    sink.add(image);
    timings.encode_s += secondsSince(phase);
    if (progress) progress(frame + 1, frames);
  }
  const auto phase = Clock::now();
  sink.finish();
  timings.encode_s += secondsSince(phase);
  timings.frames = frames;
  timings.total_s = secondsSince(start);
  return timings;
}

}  // namespace eco
