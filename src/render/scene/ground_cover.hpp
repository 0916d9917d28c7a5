// Grass and herbs on the ground near the camera (docs/rendering.md, "Ground cover"): tufts
// on a lattice fixed to the ground, each site kept or left bare by a hash of its lattice
// coordinates against the share its conditions give (light under the crowns, moisture,
// slope). A tuft stays where it is as the camera moves and a frame depends only on the
// camera, so stills and time-lapses are reproducible and nothing flickers.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/image.hpp"
#include "render/scene/culling.hpp"
#include "sim/conditions/moisture.hpp"
#include "sim/grid.hpp"
#include "sim/terrain.hpp"

namespace eco {

struct GroundCoverSettings {
  float radius_m = 0.0f;   // tufts within this distance of the eye; 0: no ground cover
  float spacing_m = 0.3f;  // of the lattice of candidate sites
};
// Stills (high) keep tufts out to 40 m, `view` (balanced) to 20 m, draft has none.
GroundCoverSettings groundCoverFor(RenderQuality quality);

enum class GroundPlant : std::uint8_t { Grass = 0, Herb = 1 };

// The share of candidate sites that hold a grass tuft and a herb, from the ground's
// conditions: `canopyCover` the share of the ground under crowns (forest_floor.hpp),
// `moisture` on Ellenberg's F scale (sim/conditions/moisture.hpp), `slope_deg`.
struct GroundCoverShares {
  float grass = 0.0f, herb = 0.0f;
};
GroundCoverShares groundCoverShares(float canopyCover, float moisture, float slope_deg);

// A tuft's height in metres for a site's moisture and the tuft's own draw in [0, 1).
float groundTuftHeight(GroundPlant plant, float moisture, float draw);

struct GroundTuft {
  glm::vec3 position{0.0f};  // world: the foot of the tuft, on the terrain's triangles
  float height_m = 0.0f;
  float yaw = 0.0f;                 // radians about the vertical
  float variation = 0.0f;           // 0..1: the tuft's own shade of its colour
  float moisture = kFreshMoisture;  // of the ground it stands on (Ellenberg F), for its colour
  GroundPlant plant = GroundPlant::Grass;
};

// The conditions of the ground the tufts are scattered by, on the terrain's grid.
class GroundCover {
 public:
  // The terrain must outlive this. Without setCanopyCover the ground is open; without
  // setMoisture it is fresh (F 5) everywhere.
  explicit GroundCover(const Terrain& terrain);
  void setCanopyCover(Field cover) { cover_ = std::move(cover); }
  void setMoisture(Field moisture) { moisture_ = std::move(moisture); }

  // The tufts within the settings' radius of `eye` whose bounds meet the frustum, in lattice
  // order (rows north to south, then west to east).
  std::vector<GroundTuft> scatter(glm::vec3 eye, const Frustum& frustum,
                                  const GroundCoverSettings& settings) const;

 private:
  const Terrain& terrain_;
  float highest_m_;  // the terrain's highest altitude
  Field slope_deg_, cover_, moisture_;
};

// The tufts' texture: a grass tuft in the left half, a woodland herb in the right, as a
// brightness (sRGB) that multiplies the plant's colour, and alpha 1 where a blade or a leaf
// is. Each half keeps a transparent margin so that mip levels do not bleed into the other.
Image makeGroundCoverAtlas();

}  // namespace eco
