#include "render/gl/background_preview.hpp"

#include "core/thread_priority.hpp"
#include "render/gl/gl_context.hpp"

namespace eco {

BackgroundPreview::BackgroundPreview(Species edited, std::vector<Species> compared,
                                     PreviewScene first)
    : worker_(
          [this, e = std::move(edited), c = std::move(compared), f = std::move(first)]() mutable {
            work(std::move(e), std::move(c), std::move(f));
          }) {}

BackgroundPreview::~BackgroundPreview() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void BackgroundPreview::request(const PreviewFrame& frame, std::optional<PreviewScene> scene) {
  {
    std::lock_guard lock(mutex_);
    frame_ = frame;
    if (scene) scenes_.push_back(std::move(*scene));
  }
  changed_.notify_all();
}

std::optional<RenderedPreview> BackgroundPreview::take() {
  std::lock_guard lock(mutex_);
  std::optional<RenderedPreview> picture = std::move(finished_);
  finished_.reset();
  return picture;
}

BackgroundPreview::Framing BackgroundPreview::framing() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return framing_.has_value() || failure_; });
  if (failure_) std::rethrow_exception(failure_);
  return *framing_;
}

void BackgroundPreview::rethrowFailure() {
  std::lock_guard lock(mutex_);
  if (failure_) std::rethrow_exception(failure_);
}

void BackgroundPreview::work(Species edited, std::vector<Species> compared, PreviewScene first) {
  lowerThisThreadsPriority();  // before the context, whose rasteriser threads inherit it
  try {
    HeadlessGl gl;
    DesignView view(edited, compared, std::move(first));
    {
      std::lock_guard lock(mutex_);
      framing_ = Framing{view.framingCamera(), view.rowCamera()};
    }
    changed_.notify_all();
    RenderTarget target;
    for (;;) {
      PreviewFrame frame;
      std::deque<PreviewScene> scenes;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [this] { return stopping_ || frame_.has_value(); });
        if (stopping_) return;
        frame = *frame_;
        frame_.reset();
        scenes.swap(scenes_);
      }
      for (PreviewScene& scene : scenes) view.show(std::move(scene));
      if (target.width != frame.size.width || target.height != frame.size.height)
        target = RenderTarget::create(frame.size.width, frame.size.height);
      const PreviewSettings& shown = view.shown().settings;
      RenderedPreview picture;
      picture.frameMs =
          view.render(frame.camera, previewRenderOptions(shown, frame.sway_ws, frame.windTime),
                      frame.row, target)
              .frameMs;
      picture.image = readPixels(target);
      picture.settings = shown;
      picture.stats = view.shown().stats;
      std::lock_guard lock(mutex_);
      finished_ = std::move(picture);
    }
  } catch (...) {
    std::lock_guard lock(mutex_);
    failure_ = std::current_exception();
    changed_.notify_all();
  }
}

}  // namespace eco
