#include "render/scene/camera_controller.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace eco {

int ViewInput::presses(ViewKey key) const {
  return static_cast<int>(std::count(pressed.begin(), pressed.end(), key));
}

void ViewInput::key(ViewKey key, bool down) {
  if (down) {
    pressed.push_back(key);
    this->down[static_cast<int>(key)] = true;
  }
  held[static_cast<int>(key)] = down;
}

void ViewInput::nextFrame() {
  down = held;
  pressed.clear();
  shortcuts.clear();
  lookDelta = glm::dvec2(0.0);
}

void CameraController::update(const ViewInput& input, float dt_s, const Terrain& terrain) {
  camera_.yaw_deg += kDegreesPerPixel * static_cast<float>(input.lookDelta.x);
  camera_.pitch_deg = std::clamp(
      camera_.pitch_deg - kDegreesPerPixel * static_cast<float>(input.lookDelta.y), -89.0f, 89.0f);
  if (!input.keyboardTaken) {
    if (input.presses(ViewKey::Walk) % 2 == 1) walking_ = !walking_;
    const float step = speed_mps_ * dt_s * (input.wasDown(ViewKey::Fast) ? 5.0f : 1.0f);
    auto axis = [&](ViewKey plus, ViewKey minus) {
      return (input.wasDown(plus) ? 1.0f : 0.0f) - (input.wasDown(minus) ? 1.0f : 0.0f);
    };
    glm::vec3 forward = camera_.forward();
    if (walking_) forward = glm::normalize(glm::vec3(forward.x, 0.0f, forward.z));
    camera_.position += step * (axis(ViewKey::Forward, ViewKey::Back) * forward +
                                axis(ViewKey::Right, ViewKey::Left) * camera_.right() +
                                axis(ViewKey::Up, ViewKey::Down) * glm::vec3(0, 1, 0));
  }
  if (walking_) camera_.position.y = groundBelow(terrain, camera_.position) + kEyeHeight_m;
}

}  // namespace eco
