// The designer's 3D preview drawn on a thread of its own, with its own headless OpenGL
// context (EGL), so that the window's thread only draws the panels and shows the newest
// finished picture: on llvmpipe a pine's frame takes longer than a window frame, and a drag
// of a control point must not wait for it. Pictures come back as images; the window uploads
// each one into a texture of its own context and shows it (no context sharing needed).
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/image.hpp"
#include "render/gl/design_view.hpp"
#include "render/scene/frame_size.hpp"

namespace eco {

// What to draw next; trees only when they changed.
struct PreviewFrame {
  OrbitCamera camera;
  bool row = true;
  double sway_ws = 0.0;  // the edited species' w_s while the wind plays, else 0
  double windTime = 0.0;
  FrameSize size;
};

struct RenderedPreview {
  Image image;
  PreviewSettings settings;  // of the trees it shows
  PreviewStats stats;
  double frameMs = 0.0;
};

class BackgroundPreview {
 public:
  // Builds the first scene's view on the thread; `first` must be complete.
  BackgroundPreview(Species edited, std::vector<Species> compared, PreviewScene first);
  ~BackgroundPreview();
  BackgroundPreview(const BackgroundPreview&) = delete;
  BackgroundPreview& operator=(const BackgroundPreview&) = delete;

  // Draws this frame next, after showing `scene` (every scene handed over is shown, in
  // order, so a complete scene is never skipped for a later partial one). Frames asked for
  // while one is drawn are dropped but the newest.
  void request(const PreviewFrame& frame, std::optional<PreviewScene> scene = std::nullopt);
  // The newest finished picture since the last call.
  std::optional<RenderedPreview> take();
  // The cameras that frame the first scene's edited tree and its whole row (known once the
  // thread has built its view).
  OrbitCamera framingCamera() { return framing().tree; }
  OrbitCamera rowCamera() { return framing().row; }
  // Rethrows on the caller's thread what failed on the preview's.
  void rethrowFailure();

 private:
  struct Framing {
    OrbitCamera tree, row;
  };
  Framing framing();
  void work(Species edited, std::vector<Species> compared, PreviewScene first);

  std::mutex mutex_;
  std::condition_variable changed_;
  std::optional<PreviewFrame> frame_;
  std::deque<PreviewScene> scenes_;
  std::optional<RenderedPreview> finished_;
  std::optional<Framing> framing_;
  std::exception_ptr failure_;
  bool stopping_ = false;
  std::thread worker_;
};

}  // namespace eco
