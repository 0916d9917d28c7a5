// Dear ImGui without a window: panels drawn into a render target on a headless context, so
// that `ecoforest design --screenshot` shows the designer as its window does (the same
// panel code, the same font and style).
#pragma once

#include <glm/vec2.hpp>

#include "render/gl/gl_objects.hpp"
#include "render/scene/frame_size.hpp"

namespace eco {

class OffscreenUi {
 public:
  OffscreenUi();  // needs a current OpenGL context (HeadlessGl)
  ~OffscreenUi();
  OffscreenUi(const OffscreenUi&) = delete;
  OffscreenUi& operator=(const OffscreenUi&) = delete;

  // Starts a frame of `size` with the pointer at `mouse` (the default: off the panels) and
  // its buttons as given: scripted input for tests.
  void beginFrame(FrameSize size, glm::vec2 mouse = {-1.0f, -1.0f}, bool leftDown = false,
                  bool rightDown = false);
  // Draws the frame's panels over what the target holds.
  void drawOnto(const RenderTarget& target);
};

}  // namespace eco
