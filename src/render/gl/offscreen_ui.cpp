#include "render/gl/offscreen_ui.hpp"

#include <epoxy/gl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

namespace eco {

OffscreenUi::OffscreenUi() {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplOpenGL3_Init("#version 450 core");
}

OffscreenUi::~OffscreenUi() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

void OffscreenUi::beginFrame(FrameSize size, glm::vec2 mouse, bool leftDown, bool rightDown) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(size.width), static_cast<float>(size.height));
  io.DeltaTime = 1.0f / 30.0f;
  io.MousePos = ImVec2(mouse.x, mouse.y);
  io.MouseDown[0] = leftDown;
  io.MouseDown[1] = rightDown;
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
}

void OffscreenUi::drawOnto(const RenderTarget& target) {
  ImGui::Render();
  target.bind();
  glDisable(GL_FRAMEBUFFER_SRGB);  // ImGui's colours are already sRGB
  // ImGui restores the program it finds current; one a destroyed renderer left current is
  // gone once ImGui's own replaces it, and restoring it would be an OpenGL error.
  glUseProgram(0);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace eco
