#include "render/gl/offscreen_ui.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include "gl_support.hpp"

namespace eco {

TEST(OffscreenUi, DrawsPanelsOverATargetAndTakesScriptedClicks) {
  test::useHeadlessGl();
  OffscreenUi ui;
  const RenderTarget target = RenderTarget::create(320, 200);
  bool clicked = false;
  // A click is a press in one frame and a release in the next.
  for (int frame = 0; frame < 4; ++frame) {
    glClearNamedFramebufferfv(target.framebuffer.id(), GL_COLOR, 0,
                              std::array<float, 4>{0, 0, 0, 1}.data());
    ui.beginFrame({320, 200}, {40.0f, 40.0f}, frame == 2);
    ImGui::SetNextWindowPos({10, 10});
    ImGui::SetNextWindowSize({200, 100});
    ImGui::Begin("panel", nullptr, ImGuiWindowFlags_NoTitleBar);
    if (ImGui::Button("button", {150, 60})) clicked = true;
    ImGui::End();
    ui.drawOnto(target);
  }
  EXPECT_TRUE(clicked);
  const Image image = readPixels(target);
  EXPECT_GT(image.get(40, 40).b, 0.2f);    // the button
  EXPECT_EQ(image.get(300, 180).r, 0.0f);  // outside the panel: what was there
}

}  // namespace eco
