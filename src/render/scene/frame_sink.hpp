// Where time-lapse frames go: numbered PNGs in a folder, or an H.264 MP4 through ffmpeg (an
// external program; scripts/setup installs it). Both write under a temporary name and rename
// when the last frame is in, so a failed or interrupted export leaves nothing half-written.
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>

#include "core/image.hpp"
#include "render/scene/frame_size.hpp"

namespace eco {

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void add(const Image& frame) = 0;
  // Completes the output (renames it into place); without it the destructor removes it.
  virtual void finish() = 0;
};

// frame_00000.png, frame_00001.png, ... in `folder`, which must not exist yet or be empty.
std::unique_ptr<FrameSink> pngFolderSink(const std::filesystem::path& folder);
// An MP4 (H.264, yuv420p, odd sizes padded to even) at `fps`. EnvironmentError when ffmpeg
// is not installed or fails; the error holds what ffmpeg said.
std::unique_ptr<FrameSink> mp4Sink(const std::filesystem::path& file, FrameSize size, int fps);

// Whether an executable of that name is on PATH.
bool programOnPath(const std::string& name);

}  // namespace eco
