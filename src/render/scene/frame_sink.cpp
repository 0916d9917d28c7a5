#include "render/scene/frame_sink.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "sim/image_io.hpp"

namespace eco {
namespace {

// "frames/" names the folder "frames".
std::filesystem::path withoutTrailingSeparator(const std::filesystem::path& folder) {
  return folder.has_filename() ? folder : folder.parent_path();
}

// Where ffmpeg's messages go: a file of this process's in the temporary folder.
std::filesystem::path ffmpegMessagesFile() {
  static std::atomic<int> count{0};
  return std::filesystem::temp_directory_path() /
         fmt::format("ecoforest-ffmpeg-{}-{}.log", ::getpid(), count++);
}

[[noreturn]] void failWith(const std::filesystem::path& file, const std::string& what,
                           const std::error_code& error) {
  throw EnvironmentError(file.string() + ": " + what + ": " + error.message());
}

class PngFolderSink : public FrameSink {
 public:
  explicit PngFolderSink(const std::filesystem::path& folder)
      : folder_(withoutTrailingSeparator(folder)),
        partial_(folder_.string() + ".partial"),
        cleanup_(partial_, InterruptCleanup::Kind::folder) {
    std::error_code error;
    if (std::filesystem::exists(folder_, error) && !std::filesystem::is_empty(folder_, error))
      throw InputError({folder_.string(), 0, "--out"}, "the frame folder exists and is not empty");
    std::filesystem::remove_all(partial_, error);
    std::filesystem::create_directories(partial_, error);
    if (error) failWith(partial_, "cannot create the folder for the frames", error);
  }
  ~PngFolderSink() override {
    std::error_code ignored;  // a destructor runs during unwinding: it must not throw
    if (!finished_) std::filesystem::remove_all(partial_, ignored);
  }
  void add(const Image& frame) override {
    writeRgb8Image(partial_ / fmt::format("frame_{:05d}.png", count_++), frame);
  }
  void finish() override {
    std::error_code error;
    std::filesystem::remove(folder_, error);  // an empty folder the user made
    std::filesystem::rename(partial_, folder_, error);
    if (error) failWith(folder_, "cannot rename the frames into place", error);
    finished_ = true;
    cleanup_.release();
    syncFolder(folder_.parent_path().empty() ? "." : folder_.parent_path());
  }

 private:
  std::filesystem::path folder_, partial_;
  InterruptCleanup cleanup_;
  int count_ = 0;
  bool finished_ = false;
};

class Mp4Sink : public FrameSink {
 public:
  Mp4Sink(const std::filesystem::path& file, int width, int height, int fps)
      : file_(file),
        partial_(file.parent_path() / (".partial_" + file.filename().string())),
        messages_(ffmpegMessagesFile()),
        cleanup_(partial_),
        messagesCleanup_(messages_) {
    if (!programOnPath("ffmpeg"))
      throw EnvironmentError(
          "MP4 output needs ffmpeg, which is not on PATH (Debian: apt-get install ffmpeg); or "
          "write PNG frames into a folder");
    // Whether the folder takes a file, before ffmpeg is started: its own message would be
    // less clear, and come only after the first frames were rendered.
    { AtomicFile probe(partial_); }
    // Raw sRGB frames in; H.264 in yuv420p, which needs even sizes: pad by a pixel if odd.
    // Converted with BT.709's matrix to limited range and tagged so (primaries, transfer,
    // matrix, range): untagged, players guess, and many guess BT.601, shifting the greens.
    const std::string command = fmt::format(
        "ffmpeg -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgb24 -s {}x{} -r {} -i - "
        "-vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2,scale=out_color_matrix=bt709:out_range=tv' "
        "-c:v libx264 -preset fast -crf 20 -pix_fmt yuv420p -colorspace bt709 "
        "-color_primaries bt709 -color_trc bt709 -color_range tv -movflags +faststart "
        "-f mp4 '{}' 2>'{}'",
        width, height, fps, partial_.string(), messages_.string());
    std::signal(SIGPIPE, SIG_IGN);  // a dying ffmpeg must give an error, not kill us
    pipe_ = popen(command.c_str(), "w");
    if (!pipe_)
      throw EnvironmentError(std::string("could not start ffmpeg: ") + std::strerror(errno));
  }
  ~Mp4Sink() override {
    if (pipe_) pclose(pipe_);
    std::error_code ignored;  // a destructor runs during unwinding: it must not throw
    if (!finished_) std::filesystem::remove(partial_, ignored);
    std::filesystem::remove(messages_, ignored);
  }
  void add(const Image& frame) override {
    const std::vector<std::uint8_t> rgb = frame.rgb();
    if (std::fwrite(rgb.data(), 1, rgb.size(), pipe_) != rgb.size()) fail();
  }
  void finish() override {
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    // ffmpeg reports only errors (-loglevel error), and some -- a full disk while it writes
    // the MP4's index -- with exit status 0: any message, like a non-zero status or an empty
    // file, is a failure.
    std::error_code error;
    if (status != 0 || !messages().empty() || std::filesystem::file_size(partial_, error) == 0 ||
        error)
      fail();
    const int descriptor = ::open(partial_.c_str(), O_RDONLY | O_CLOEXEC);
    const bool synced = descriptor >= 0 && ::fsync(descriptor) == 0;
    if (descriptor >= 0) ::close(descriptor);
    if (!synced) fail();
    std::filesystem::rename(partial_, file_, error);
    if (error) failWith(file_, "cannot rename the video into place", error);
    finished_ = true;
    cleanup_.release();
    syncFolder(file_.parent_path().empty() ? "." : file_.parent_path());
  }

 private:
  // What ffmpeg wrote to its standard error.
  std::string messages() const {
    std::ifstream in(messages_);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  [[noreturn]] void fail() {
    if (pipe_) pclose(pipe_);
    pipe_ = nullptr;
    std::string said = messages();
    while (!said.empty() && said.back() == '\n') said.pop_back();
    throw EnvironmentError(file_.string() + ": ffmpeg failed to encode it" +
                           (said.empty() ? std::string() : ": " + said));
  }

  std::filesystem::path file_, partial_, messages_;
  InterruptCleanup cleanup_, messagesCleanup_;
  FILE* pipe_ = nullptr;
  bool finished_ = false;
};

}  // namespace

bool programOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream folders(path);
  for (std::string folder; std::getline(folders, folder, ':');)
    if (!folder.empty() && access((std::filesystem::path(folder) / name).c_str(), X_OK) == 0)
      return true;
  return false;
}

std::unique_ptr<FrameSink> pngFolderSink(const std::filesystem::path& folder) {
  return std::make_unique<PngFolderSink>(folder);
}

std::unique_ptr<FrameSink> mp4Sink(const std::filesystem::path& file, FrameSize size, int fps) {
  return std::make_unique<Mp4Sink>(file, size.width, size.height, fps);
}

}  // namespace eco
