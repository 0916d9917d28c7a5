// OpenGL contexts. Rendering without a display goes through EGL on Mesa's surfaceless
// platform (no X server, no GPU needed: llvmpipe gives OpenGL 4.5); the window of
// `ecoforest view` comes from GLFW. Both load functions through libepoxy.
#pragma once

#include <string>

namespace eco {

inline constexpr int kGlMajor = 4;
inline constexpr int kGlMinor = 5;

// A current OpenGL 4.5 core context with no default framebuffer: draw into framebuffer
// objects. One per thread; throws EnvironmentError when EGL or the context is missing.
class HeadlessGl {
 public:
  HeadlessGl();
  ~HeadlessGl();
  HeadlessGl(const HeadlessGl&) = delete;
  HeadlessGl& operator=(const HeadlessGl&) = delete;

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
};

// "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6" for the current context.
std::string glDescription();

}  // namespace eco
