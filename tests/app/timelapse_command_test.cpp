// Runs `ecoforest timelapse` as a user would.
#include <gtest/gtest.h>

#include "app_support.hpp"

namespace {

using eco::test::CommandResult;
using eco::test::ecoforest;
using eco::test::shortDefaultRun;

TEST(TimelapseCommand, AnMp4HasFpsTimesSecondsFramesAtTheRequestedSize) {
  if (eco::test::runCommand("command -v ffprobe").exitCode != 0)
    GTEST_SKIP() << "ffmpeg is not installed (scripts/setup installs it)";
  const auto out = eco::test::freshDirectory("app_timelapse_mp4") / "growth.mp4";
  CommandResult r =
      ecoforest("timelapse " + shortDefaultRun().string() +
                " --seconds 1.5 --fps 8 --size 160x96 --overlay --out " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  CommandResult probe = eco::test::runCommand(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=nb_read_frames,width,height,pix_fmt,codec_name -of csv=p=0 " +
      out.string());
  EXPECT_EQ(probe.output, "h264,160,96,yuv420p,12\n");
}

TEST(TimelapseCommand, PngFramesAreCountedAndIdenticalForTheSameRunAndOptions) {
  const auto dir = eco::test::freshDirectory("app_timelapse_png");
  const std::string options =
      " --kind wind --seconds 0.5 --fps 10 --size 128x80 --camera-path flyover";
  for (const char* name : {"a", "b/"}) {  // a folder may be given with its slash
    CommandResult r = ecoforest("timelapse " + shortDefaultRun().string() + options + " --out " +
                                (dir / name).string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
  }
  ASSERT_EQ(eco::test::entriesIn(dir / "a"), 5u);
  for (int f = 0; f < 5; ++f) {
    const std::string frame = "frame_0000" + std::to_string(f) + ".png";
    EXPECT_EQ(eco::test::readFile(dir / "a" / frame), eco::test::readFile(dir / "b" / frame))
        << frame;
  }
}

TEST(TimelapseCommand, AFullDiskOrAReadOnlyFolderIsAClearErrorAndLeavesNothing) {
  const std::string frames = "timelapse " + shortDefaultRun().string() +
                             " --seconds 2 --fps 10 --size 320x180" +
                             " --quality draft";  // the test is about files, not pictures
  eco::test::expectFullAndReadOnlyDisksFailCleanly(frames + " --out \"$SPACE/frames\"", 16,
                                                   "No space left on device");
  if (eco::test::runCommand("command -v ffmpeg").exitCode != 0)
    GTEST_SKIP() << "ffmpeg is not installed (scripts/setup installs it)";
  eco::test::expectFullAndReadOnlyDisksFailCleanly(frames + " --out \"$SPACE/t.mp4\"", 16,
                                                   "t.mp4: ffmpeg failed to encode it");
}

// Ctrl-C while the frames are being written: exit 130 and neither the frame folder nor the
// video nor a partial one is left.
TEST(TimelapseCommand, CtrlCLeavesNothingPartial) {
  const auto dir = eco::test::freshDirectory("app_timelapse_interrupt");
  const std::string timelapse = "timelapse " + shortDefaultRun().string() +
                                " --seconds 60 --fps 10 --size 160x96" +
                                " --quality draft";  // the test is about files, not pictures
  CommandResult frames = eco::test::interruptWhen(
      timelapse + " --out " + (dir / "frames").string(),
      "[ -e " + (dir / "frames.partial" / "frame_00002.png").string() + " ]");
  EXPECT_EQ(frames.exitCode, 130) << frames.output;
  EXPECT_EQ(eco::test::entriesIn(dir), 0u);
  if (eco::test::runCommand("command -v ffmpeg").exitCode != 0)
    GTEST_SKIP() << "ffmpeg is not installed (scripts/setup installs it)";
  CommandResult video =
      eco::test::interruptWhen(timelapse + " --out " + (dir / "t.mp4").string(),
                               "[ -s " + (dir / ".partial_t.mp4").string() + " ]");
  EXPECT_EQ(video.exitCode, 130) << video.output;
  EXPECT_EQ(eco::test::entriesIn(dir), 0u);
}

TEST(TimelapseCommand, BadInputIsExitTwoAndLeavesNoFile) {
  const auto dir = eco::test::freshDirectory("app_timelapse_bad");
  const std::string run = shortDefaultRun().string();
  const std::string out = " --out " + (dir / "t.mp4").string();
  auto expectError = [&](const std::string& arguments, const std::string& message) {
    CommandResult r = ecoforest("timelapse " + arguments);
    EXPECT_EQ(r.exitCode, 2) << arguments << ": " << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << arguments << ": " << r.output;
  };
  expectError((dir / "none").string() + out, "no such run folder");
  expectError(run + " --years 0:90" + out, "0 <= A < B <= 20");
  expectError(run + " --years soon" + out, "expected A:B");
  expectError(run + " --kind wind --years 15" + out, "no snapshot of year 15");
  expectError(run + " --out " + (dir / "x.avi").string(), "FILE.mp4");
  expectError(run + " --out " + (dir / "missing" / "t.mp4").string(), "folder does not exist");
  expectError(run + " --camera-path " + (dir / "nope.toml").string() + out, "nope.toml");
  // Without ffmpeg on PATH an MP4 cannot be made; ecoforest says so, with the environment's
  // exit code.
  CommandResult noFfmpeg = eco::test::runCommand(
      "env PATH=/nonexistent " + std::string(ECOFOREST_EXE) + " timelapse " + run + out);
  EXPECT_EQ(noFfmpeg.exitCode, 3) << noFfmpeg.output;
  EXPECT_NE(noFfmpeg.output.find("needs ffmpeg"), std::string::npos) << noFfmpeg.output;
  EXPECT_EQ(eco::test::entriesIn(dir), 0u);
}

}  // namespace
