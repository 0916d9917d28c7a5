// Flying and walking the camera of `ecoforest view`, apart from any window so that it can be
// tested without one: the window turns its events into a ViewInput, and update() moves the
// camera by it. Key taps are events, not the keys' state once a frame, so a tap shorter than
// a frame (at a few frames per second on llvmpipe) still counts.
#pragma once

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "render/scene/camera.hpp"
#include "sim/terrain.hpp"

namespace eco {

enum class ViewKey { Forward, Back, Left, Right, Down, Up, Fast, Walk, Screenshot, Play, Count };
inline constexpr int kViewKeyCount = static_cast<int>(ViewKey::Count);

// A letter key pressed with Ctrl (a command such as Ctrl+Z), as an event.
struct Shortcut {
  char letter = 'A';  // 'A'..'Z'
  bool shift = false;
  bool operator==(const Shortcut&) const = default;
};

// What the user did since the previous frame.
struct ViewInput {
  std::array<bool, kViewKeyCount> held{};  // down at the end of the frame
  // Down at any moment of the frame: held when it began, or pressed during it. Movement
  // follows this, so a tap between two polls moves the camera for one frame.
  std::array<bool, kViewKeyCount> down{};
  std::vector<ViewKey> pressed;     // went down during it, in order (taps included)
  glm::dvec2 lookDelta{0.0};        // pixels the pointer moved with the look button held
  bool keyboardTaken = false;       // the panel has the keyboard (a text field)
  std::vector<Shortcut> shortcuts;  // Ctrl+letter presses during it, in order

  bool isHeld(ViewKey key) const { return held[static_cast<int>(key)]; }
  bool wasDown(ViewKey key) const { return down[static_cast<int>(key)]; }
  int presses(ViewKey key) const;
  // Feeds one key event: down (press) or up (release).
  void key(ViewKey key, bool down);
  // Clears the events of a frame, keeping which keys are held (and so down in the next).
  void nextFrame();
};

class CameraController {
 public:
  CameraController(Camera camera, bool walking) : camera_(camera), walking_(walking) {}

  // Turns with the look delta, moves dt seconds along each key that was down during the
  // frame (W A S D, Q E down and up, Shift five times faster) and toggles walking on each
  // tap of G; a walker's eyes stay kEyeHeight_m above the ground.
  void update(const ViewInput& input, float dt_s, const Terrain& terrain);

  const Camera& camera() const { return camera_; }
  bool walking() const { return walking_; }
  void setWalking(bool walking) { walking_ = walking; }
  float& speed_mps() { return speed_mps_; }

  static constexpr float kEyeHeight_m = 1.7f;
  static constexpr float kDegreesPerPixel = 0.15f;

 private:
  Camera camera_;
  bool walking_ = false;
  float speed_mps_ = 20.0f;
};

}  // namespace eco
