#include "render/scene/frame_sink.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

Image solid(int w, int h, std::uint8_t shade) {
  Image image(w, h);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = (i % 4 == 3) ? 255 : shade;
  return image;
}

TEST(FrameSink, PngFramesAppearOnlyWhenFinished) {
  const auto dir = test::freshDirectory("frame_sink");
  {
    auto sink = pngFolderSink(dir / "frames");
    for (int i = 0; i < 3; ++i) sink->add(solid(32, 16, 40 * i));
    EXPECT_FALSE(std::filesystem::exists(dir / "frames"));
    sink->finish();
  }
  EXPECT_EQ(test::entriesIn(dir / "frames"), 3u);
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "frame_00002.png"));
  EXPECT_EQ(test::readPng(dir / "frames" / "frame_00001.png").rgba[0], 40);
  {
    auto abandoned = pngFolderSink(dir / "abandoned");
    abandoned->add(solid(32, 16, 0));
  }  // never finished: nothing stays behind
  EXPECT_EQ(test::entriesIn(dir), 1u);
  EXPECT_THROW(pngFolderSink(dir / "frames"), InputError);  // not empty
}

TEST(FrameSink, Mp4HasEveryFrameAtAnEvenSize) {
  if (!programOnPath("ffmpeg") || !programOnPath("ffprobe"))
    GTEST_SKIP() << "ffmpeg is not installed (Debian: ffmpeg)";
  const auto dir = test::freshDirectory("frame_sink_mp4");
  {
    auto sink = mp4Sink(dir / "clip.mp4", {33, 17}, 10);
    for (int i = 0; i < 7; ++i) sink->add(solid(33, 17, 30 * i));
    sink->finish();
  }
  const test::CommandResult probe = test::runCommand(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=nb_read_frames,width,height,pix_fmt -of csv=p=0 " +
      (dir / "clip.mp4").string());
  EXPECT_EQ(probe.output, "34,18,yuv420p,7\n");
  EXPECT_EQ(test::entriesIn(dir), 1u);  // no temporary file left
  // Tagged BT.709, limited range, so players do not guess.
  const test::CommandResult colour = test::runCommand(
      "ffprobe -v error -select_streams v:0 -show_entries "
      "stream=color_range,color_space,color_transfer,color_primaries -of csv=p=0 " +
      (dir / "clip.mp4").string());
  EXPECT_EQ(colour.output, "tv,bt709,bt709,bt709\n");
}

TEST(FrameSink, FindsProgramsOnThePath) {
  EXPECT_TRUE(programOnPath("sh"));
  EXPECT_FALSE(programOnPath("no-such-program-ecoforest"));
}

}  // namespace
}  // namespace eco
