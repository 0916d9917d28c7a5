#include "render/gl/window.hpp"

#include <optional>
#include <utility>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "core/error.hpp"
#include "render/gl/gl_context.hpp"

namespace eco {
namespace {

// The keys of the view and what each does.
constexpr std::pair<int, ViewKey> kKeys[] = {
    {GLFW_KEY_W, ViewKey::Forward},       {GLFW_KEY_S, ViewKey::Back},
    {GLFW_KEY_A, ViewKey::Left},          {GLFW_KEY_D, ViewKey::Right},
    {GLFW_KEY_Q, ViewKey::Down},          {GLFW_KEY_E, ViewKey::Up},
    {GLFW_KEY_LEFT_SHIFT, ViewKey::Fast}, {GLFW_KEY_RIGHT_SHIFT, ViewKey::Fast},
    {GLFW_KEY_G, ViewKey::Walk},          {GLFW_KEY_P, ViewKey::Screenshot},
    {GLFW_KEY_SPACE, ViewKey::Play}};

std::optional<ViewKey> viewKeyOf(int key) {
  for (auto [glfwKey, viewKey] : kKeys)
    if (glfwKey == key) return viewKey;
  return std::nullopt;
}

}  // namespace

Window::Window(const std::string& title, FrameSize size, const std::string& command,
               const std::string& withoutDisplay) {
  if (!glfwInit())
    throw EnvironmentError(command + " needs a display and none could be opened; " +
                           withoutDisplay);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, kGlMajor);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, kGlMinor);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(size.width, size.height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw EnvironmentError(command + " could not open an OpenGL 4.5 window on this display");
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  glfwSetWindowUserPointer(window_, this);
  // Installed before ImGui's, which chains to it.
  glfwSetKeyCallback(window_, onKey);
  glfwGetCursorPos(window_, &lastX_, &lastY_);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
}

Window::~Window() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void Window::onKey(GLFWwindow* window, int key, int, int action, int mods) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (!self) return;
  // Ctrl+letter: a command, kept as an event so that a quick chord (shorter than a frame
  // at a few frames per second) is not lost between two polls.
  if (action == GLFW_PRESS && (mods & GLFW_MOD_CONTROL) && key >= GLFW_KEY_A && key <= GLFW_KEY_Z) {
    self->input_.shortcuts.push_back(
        {static_cast<char>('A' + (key - GLFW_KEY_A)), (mods & GLFW_MOD_SHIFT) != 0});
    return;
  }
  const std::optional<ViewKey> viewKey = viewKeyOf(key);
  if (!viewKey || action == GLFW_REPEAT) return;
  self->input_.key(*viewKey, action == GLFW_PRESS);
}

bool Window::shouldClose() const {
  return glfwWindowShouldClose(window_);
}

double Window::seconds() const {
  return glfwGetTime();
}

const ViewInput& Window::beginFrame() {
  input_.nextFrame();
  glfwPollEvents();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const ImGuiIO& io = ImGui::GetIO();
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window_, &x, &y);
  if (!io.WantCaptureMouse && glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS)
    input_.lookDelta = {x - lastX_, y - lastY_};
  lastX_ = x, lastY_ = y;
  input_.keyboardTaken = io.WantCaptureKeyboard;
  return input_;
}

FrameSize Window::framebufferSize() const {
  FrameSize size{0, 0};
  glfwGetFramebufferSize(window_, &size.width, &size.height);
  return size;
}

void Window::present(const RenderTarget& target) {
  if (target.width > 0) {
    // A target smaller than the window (view's dynamic resolution) is magnified, filtered;
    // a multisampled one is resolved first, since one blit cannot do both.
    const FrameSize window = framebufferSize();
    const bool magnified = window.width != target.width || window.height != target.height;
    if (magnified) target.resolve();
    const GLuint source =
        magnified && target.samples > 1 ? target.resolved.id() : target.framebuffer.id();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, target.width, target.height, 0, 0, window.width, window.height,
                      GL_COLOR_BUFFER_BIT, magnified ? GL_LINEAR : GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_FRAMEBUFFER_SRGB);  // ImGui's colours are already sRGB
  }
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(window_);
}

}  // namespace eco
