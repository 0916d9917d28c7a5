#include "render/gl/gl_context.hpp"

#include <stdexcept>

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <fmt/format.h>

#include "core/error.hpp"

namespace eco {
namespace {

[[noreturn]] void eglFailure(const char* what) {
  throw EnvironmentError(
      fmt::format("headless OpenGL: {} failed (EGL error 0x{:x}); ecoforest needs Mesa's EGL "
                  "(Debian: libegl-mesa0, libgl1-mesa-dri)",
                  what, static_cast<unsigned>(eglGetError())));
}

}  // namespace

HeadlessGl::HeadlessGl() {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) eglFailure("eglGetPlatformDisplayEXT");
  EGLDisplay display =
      getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) eglFailure("the surfaceless display");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) eglFailure("eglInitialize");
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API)) eglFailure("eglBindAPI(OpenGL)");

  const EGLint configAttributes[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                     EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  eglChooseConfig(display, configAttributes, &config, 1, &configs);
  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      kGlMajor,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      kGlMinor,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
  EGLContext context = eglCreateContext(display, configs > 0 ? config : EGL_NO_CONFIG_KHR,
                                        EGL_NO_CONTEXT, contextAttributes);
  if (context == EGL_NO_CONTEXT) eglFailure("creating an OpenGL 4.5 core context");
  context_ = context;
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    eglFailure("eglMakeCurrent");
}

HeadlessGl::~HeadlessGl() {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_) eglDestroyContext(display_, context_);
  // The display stays initialised: EGL displays are shared per process, and terminating it
  // would break another context still in use.
}

std::string glDescription() {
  return fmt::format("{} | {}", reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                     reinterpret_cast<const char*>(glGetString(GL_VERSION)));
}

}  // namespace eco
