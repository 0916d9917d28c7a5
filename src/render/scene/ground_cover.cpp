#include "render/scene/ground_cover.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/frames.hpp"
#include "core/random.hpp"
#include "sim/conditions/moisture.hpp"
#include "sim/conditions/slope.hpp"
#include "sim/ecology/seedbed.hpp"

namespace eco {
namespace {

constexpr int kAtlasHalf = 256;  // each plant's square of the atlas

// A texture square painted by `paint(u, v)` (u across, v up from the tuft's foot, both in
// [0, 1]), which returns the brightness and whether a blade or leaf is there.
template <typename Paint>
void paintSquare(Image& atlas, int left, Paint paint) {
  for (int y = 0; y < kAtlasHalf; ++y)
    for (int x = 0; x < kAtlasHalf; ++x) {
      const float u = (x + 0.5f) / kAtlasHalf, v = (y + 0.5f) / kAtlasHalf;
      const auto [color, inside] = paint(u, v);
      // Outside, the colour is the plant's mean, so that filtering does not darken edges.
      atlas.set(left + x, y, glm::vec4(color, inside ? 1.0f : 0.0f));
    }
}

// 28 blades from a clump about a tenth of the square wide, leaning out and curving over,
// darker at the foot and yellower at the tips.
std::pair<glm::vec3, bool> grassAt(float u, float v) {
  constexpr int kBlades = 28;
  const glm::vec3 mean(0.72f, 0.78f, 0.62f);
  for (int b = 0; b < kBlades; ++b) {
    Rng rng(streamKey(static_cast<std::uint64_t>(b), purpose("grass blade")));
    const float foot = 0.5f + 0.12f * static_cast<float>(rng.uniform(-1.0, 1.0));
    const float lean = 0.55f * static_cast<float>(rng.uniform(-1.0, 1.0));
    const float length = static_cast<float>(rng.uniform(0.55, 0.95));
    const float shade = static_cast<float>(rng.uniform(0.85, 1.1));
    const float s = v / length;  // along the blade, 0 at the foot
    if (s > 1.0f) continue;
    // The blade leans more as it rises (its tip bends over).
    const float centre = foot + length * (0.5f * lean * s + 0.35f * lean * s * s);
    const float halfWidth = 0.012f * std::pow(1.0f - s, 0.7f) + 0.002f;
    if (std::abs(u - centre) < halfWidth && centre > 0.03f && centre < 0.97f) {
      const float brightness = shade * (0.6f + 0.4f * s);
      const glm::vec3 tint =
          glm::mix(glm::vec3(0.95f, 1.0f, 0.9f), glm::vec3(1.0f, 0.95f, 0.7f), s * s);
      return {glm::min(brightness * tint, glm::vec3(1.0f)), true};
    }
  }
  return {mean, false};
}

// A woodland herb (dog's mercury, woodruff): four stalks with pairs of oval leaves at two
// or three nodes, a lighter midrib along each leaf.
std::pair<glm::vec3, bool> herbAt(float u, float v) {
  constexpr int kStalks = 4;
  const glm::vec3 mean(0.8f, 0.85f, 0.75f);
  for (int k = 0; k < kStalks; ++k) {
    Rng rng(streamKey(static_cast<std::uint64_t>(k), purpose("herb stalk")));
    const float foot = 0.5f + 0.1f * static_cast<float>(rng.uniform(-1.0, 1.0));
    const float lean = 0.25f * static_cast<float>(rng.uniform(-1.0, 1.0));
    const float top = static_cast<float>(rng.uniform(0.55, 0.85));
    const int nodes = 2 + static_cast<int>(rng.uniform(0.0, 2.0));
    auto stalkU = [&](float along) { return foot + lean * along; };
    if (v < top && std::abs(u - stalkU(v)) < 0.007f) return {glm::vec3(0.7f, 0.8f, 0.55f), true};
    for (int n = 0; n < nodes; ++n) {
      const float nodeV = top * (0.45f + 0.55f * (n + 1) / nodes);
      for (float side : {-1.0f, 1.0f}) {
        // An oval leaf 0.17 long and 0.07 wide, rising at 35 degrees from the node.
        const float angle = (side > 0 ? 0.0f : std::numbers::pi_v<float>)+side *
                            0.61f;  // 35 degrees above the horizontal
        const glm::vec2 axis(std::cos(angle), std::sin(angle));
        const glm::vec2 centre = glm::vec2(stalkU(nodeV), nodeV) + 0.095f * axis;
        const glm::vec2 d(u - centre.x, v - centre.y);
        const float along = glm::dot(d, axis), across = axis.x * d.y - axis.y * d.x;
        const float r = (along * along) / (0.085f * 0.085f) + (across * across) / (0.035f * 0.035f);
        if (r < 1.0f) {
          const float brightness =
              std::abs(across) < 0.004f ? 1.0f : 0.78f + 0.12f * along / 0.085f;
          return {glm::vec3(brightness), true};
        }
      }
    }
  }
  return {mean, false};
}

}  // namespace

GroundCoverSettings groundCoverFor(RenderQuality quality) {
  switch (quality) {
    case RenderQuality::Draft:
      return {0.0f, 0.3f};
    case RenderQuality::Balanced:
      return {20.0f, 0.3f};
    case RenderQuality::High:
      return {40.0f, 0.3f};
  }
  return {};
}

GroundCoverShares groundCoverShares(float canopyCover, float moisture, float slope_deg) {
  const float canopy = std::clamp(canopyCover, 0.0f, 1.0f);
  GroundCoverShares shares;
  // The sward the simulation's seeds fall into (sim/ecology/seedbed.hpp).
  shares.grass = swardShare(1.0f - canopy, moisture, slope_deg);
  // Woodland herbs (L 2-5, F 5-6: wood anemone, woodruff, dog's mercury) carpet fresh soils
  // under an open canopy; under the deepest shade the floor is bare litter.
  shares.herb = 0.3f * glm::smoothstep(0.2f, 0.6f, canopy) *
                (1.0f - 0.7f * glm::smoothstep(0.85f, 1.0f, canopy)) *
                glm::smoothstep(3.0f, 5.0f, moisture) * soilShareOnSlope(slope_deg);
  return shares;
}

float groundTuftHeight(GroundPlant plant, float moisture, float draw) {
  if (plant == GroundPlant::Herb) return 0.12f + 0.12f * draw;
  // Full height on fresh ground (F 5), shorter on dry; the sedges and rushes of wet ground
  // stand taller.
  return (0.25f + 0.3f * draw) * (0.7f + 0.3f * glm::smoothstep(3.0f, 5.0f, moisture)) *
         (1.0f + 0.5f * glm::smoothstep(6.5f, 8.5f, moisture));
}

GroundCover::GroundCover(const Terrain& terrain)
    : terrain_(terrain), highest_m_(static_cast<float>(statsOf(terrain.height_m).max)) {
  Field aspect_deg;
  computeSlopeAspect(terrain, slope_deg_, aspect_deg);
}

std::vector<GroundTuft> GroundCover::scatter(glm::vec3 eye, const Frustum& frustum,
                                             const GroundCoverSettings& settings) const {
  std::vector<GroundTuft> tufts;
  if (settings.radius_m <= 0.0f || settings.spacing_m <= 0.0f) return tufts;
  if (eye.y - highest_m_ > settings.radius_m) return tufts;  // above every tuft's reach
  const Grid& grid = terrain_.grid;
  const glm::dvec3 eyeMap = mapFromWorld(eye);
  const double spacing = settings.spacing_m, radius = settings.radius_m;
  const double lastEast = grid.eastOf(grid.width - 1), lastNorth = grid.northOf(0);
  const auto first = [&](double centre) {
    return static_cast<long>(std::floor((centre - radius) / spacing));
  };
  const long iFirst = first(eyeMap.x), jFirst = first(eyeMap.y);
  const long sites = static_cast<long>(std::ceil(2.0 * radius / spacing)) + 1;
  for (long j = jFirst + sites; j >= jFirst; --j)
    for (long i = iFirst; i <= iFirst + sites; ++i) {
      Rng rng(streamKey(static_cast<std::uint64_t>(i), static_cast<std::uint64_t>(j),
                        purpose("ground cover")));
      const double east = (static_cast<double>(i) + rng.uniform()) * spacing;
      const double north = (static_cast<double>(j) + rng.uniform()) * spacing;
      const double de = east - eyeMap.x, dn = north - eyeMap.y;
      if (de * de + dn * dn > radius * radius) continue;
      if (east < 0.0 || north < 0.0 || east > lastEast || north > lastNorth) continue;
      const long cell = grid.cellAt(east, north);
      if (cell < 0 || terrain_.isOutside(static_cast<std::size_t>(cell))) continue;
      const glm::vec3 foot = worldFromMap(east, north, terrain_.altitudeAt(east, north));
      if (glm::distance(foot, eye) > settings.radius_m) continue;
      const float cover = cover_.empty() ? 0.0f : sampleBilinear(grid, cover_, east, north);
      float moisture =
          moisture_.empty() ? kFreshMoisture : sampleBilinear(grid, moisture_, east, north);
      if (!std::isfinite(moisture)) moisture = kFreshMoisture;  // beside an outside cell
      const GroundCoverShares shares =
          groundCoverShares(cover, moisture, sampleBilinear(grid, slope_deg_, east, north));
      const double draw = rng.uniform();
      if (draw >= shares.grass + shares.herb) continue;
      GroundTuft tuft;
      tuft.plant = draw < shares.grass ? GroundPlant::Grass : GroundPlant::Herb;
      tuft.position = foot;
      tuft.height_m = groundTuftHeight(tuft.plant, moisture, static_cast<float>(rng.uniform()));
      if (!frustum.intersectsSphere(foot + glm::vec3(0.0f, 0.5f * tuft.height_m, 0.0f),
                                    tuft.height_m))
        continue;
      tuft.yaw = static_cast<float>(rng.uniform(0.0, 2.0 * std::numbers::pi));
      tuft.variation = static_cast<float>(rng.uniform());
      tuft.moisture = moisture;
      tufts.push_back(tuft);
    }
  return tufts;
}

Image makeGroundCoverAtlas() {
  Image atlas(2 * kAtlasHalf, kAtlasHalf);
  paintSquare(atlas, 0, grassAt);
  paintSquare(atlas, kAtlasHalf, herbAt);
  return atlas;
}

}  // namespace eco
