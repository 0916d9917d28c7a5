// The window of `ecoforest view`: GLFW with an OpenGL 4.5 core context and Dear ImGui on it,
// owned for its whole life by this object (RAII), so a frame that throws still closes the
// window and shuts ImGui and GLFW down. Keys arrive through callbacks as events
// (camera_controller.hpp), not as the keys' state polled once a frame.
#pragma once

#include <string>

#include "render/gl/gl_objects.hpp"
#include "render/scene/camera_controller.hpp"
#include "render/scene/frame_size.hpp"

struct GLFWwindow;

namespace eco {

class Window {
 public:
  // EnvironmentError when there is no display or no OpenGL 4.5 on it; its message names
  // `command` and ends with `withoutDisplay` (what to use instead).
  Window(const std::string& title, FrameSize size, const std::string& command,
         const std::string& withoutDisplay);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  bool shouldClose() const;
  // Polls events and starts an ImGui frame; returns what the user did since the last call.
  const ViewInput& beginFrame();
  double seconds() const;  // since the window opened
  FrameSize framebufferSize() const;
  // Copies the target onto the window (magnified where it is smaller), draws the ImGui frame
  // over it and shows the result.
  void present(const RenderTarget& target);

 private:
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);

  GLFWwindow* window_ = nullptr;
  ViewInput input_;
  double lastX_ = 0.0, lastY_ = 0.0;
};

}  // namespace eco
