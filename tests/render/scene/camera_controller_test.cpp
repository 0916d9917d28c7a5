#include "render/scene/camera_controller.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "render_support.hpp"

namespace eco {
namespace {

// A frame of 0.2 s (5 frames per second) in which the key went down and up again.
ViewInput tap(ViewKey key) {
  ViewInput input;
  input.key(key, true);
  input.key(key, false);
  return input;
}

TEST(CameraController, ATapShorterThanAFrameStillCounts) {
  const Terrain terrain = test::flatTerrain(9, 10.0);
  CameraController controller(Camera{}, false);
  const ViewInput g = tap(ViewKey::Walk);
  EXPECT_FALSE(g.isHeld(ViewKey::Walk));
  EXPECT_EQ(g.presses(ViewKey::Walk), 1);
  controller.update(g, 0.2f, terrain);
  EXPECT_TRUE(controller.walking());
  // Two taps within one frame toggle twice.
  ViewInput twice = tap(ViewKey::Walk);
  twice.key(ViewKey::Walk, true);
  twice.key(ViewKey::Walk, false);
  controller.update(twice, 0.2f, terrain);
  EXPECT_TRUE(controller.walking());
  // The next frame starts without the events but keeps what is held.
  ViewInput held;
  held.key(ViewKey::Forward, true);
  held.nextFrame();
  EXPECT_TRUE(held.pressed.empty());
  EXPECT_TRUE(held.isHeld(ViewKey::Forward));
}

TEST(CameraController, MovementKeysTappedAtFiveFramesPerSecondAllMoveTheCamera) {
  const Terrain terrain = test::flatTerrain(33, 10.0);
  Camera start;
  start.yaw_deg = 90.0f;  // looking east
  CameraController controller(start, false);
  ViewInput input;
  const float frame_s = 0.2f;
  // Ten taps of W, each down and up between two polls of the window: every one moves the
  // camera by a frame's step (20 m/s for 0.2 s), none is lost.
  for (int i = 0; i < 10; ++i) {
    input.nextFrame();
    input.key(ViewKey::Forward, true);
    input.key(ViewKey::Forward, false);
    controller.update(input, frame_s, terrain);
  }
  EXPECT_NEAR(controller.camera().position.x - start.position.x, 40.0f, 1e-3f);
  // Frames without a key do not move it.
  input.nextFrame();
  controller.update(input, frame_s, terrain);
  EXPECT_NEAR(controller.camera().position.x - start.position.x, 40.0f, 1e-3f);
  // A key held from an earlier frame and let go during this one still moves it this frame,
  // and not the next.
  input.nextFrame();
  input.key(ViewKey::Back, true);
  controller.update(input, frame_s, terrain);
  input.nextFrame();
  input.key(ViewKey::Back, false);
  controller.update(input, frame_s, terrain);
  input.nextFrame();
  controller.update(input, frame_s, terrain);
  EXPECT_NEAR(controller.camera().position.x - start.position.x, 32.0f, 1e-3f);
}

TEST(CameraController, ShortcutsAreEventsOfOneFrame) {
  ViewInput input;
  input.shortcuts.push_back({'S', false});
  input.shortcuts.push_back({'Z', true});
  EXPECT_EQ(input.shortcuts[1], (Shortcut{'Z', true}));
  input.nextFrame();
  EXPECT_TRUE(input.shortcuts.empty());
}

TEST(CameraController, HeldKeysMoveAtTheSpeedAndWalkersStayAtEyeHeight) {
  const Terrain terrain = test::flatTerrain(33, 10.0);
  Camera start;
  start.position = worldFromMap(100.0, 100.0, 300.0);
  start.yaw_deg = 90.0f;  // looking east
  CameraController flyer(start, false);
  ViewInput input;
  input.key(ViewKey::Forward, true);
  flyer.update(input, 0.5f, terrain);
  EXPECT_NEAR(glm::distance(flyer.camera().position, start.position), 10.0f, 1e-3f);  // 20 m/s
  EXPECT_GT(flyer.camera().position.x, start.position.x);
  input.key(ViewKey::Fast, true);
  const glm::vec3 before = flyer.camera().position;
  flyer.update(input, 0.5f, terrain);
  EXPECT_NEAR(glm::distance(flyer.camera().position, before), 50.0f, 1e-3f);

  CameraController walker(start, true);
  walker.update(ViewInput{}, 0.1f, terrain);
  EXPECT_NEAR(walker.camera().position.y,
              groundBelow(terrain, walker.camera().position) + CameraController::kEyeHeight_m,
              1e-4f);
}

TEST(CameraController, TheKeyboardGoesToThePanelWhenItAsks) {
  const Terrain terrain = test::flatTerrain(9, 10.0);
  CameraController controller(Camera{}, false);
  ViewInput input = tap(ViewKey::Walk);
  input.key(ViewKey::Forward, true);
  input.keyboardTaken = true;
  controller.update(input, 0.2f, terrain);
  EXPECT_FALSE(controller.walking());
  EXPECT_EQ(controller.camera().position, Camera{}.position);
}

TEST(CameraController, LookingTurnsAndStopsShortOfTheVertical) {
  const Terrain terrain = test::flatTerrain(9, 10.0);
  CameraController controller(Camera{}, false);
  ViewInput input;
  input.lookDelta = {100.0, -10000.0};
  controller.update(input, 0.0f, terrain);
  EXPECT_FLOAT_EQ(controller.camera().yaw_deg, 15.0f);
  EXPECT_FLOAT_EQ(controller.camera().pitch_deg, 89.0f);
}

}  // namespace
}  // namespace eco
