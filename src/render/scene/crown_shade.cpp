#include "render/scene/crown_shade.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "model/mesh/lod.hpp"
#include "render/scene/wind_mesh.hpp"

namespace eco {
namespace {

// Cosine-weighted directions over the upper hemisphere (Hammersley points, Malley's method:
// uniform on the disc, lifted to the hemisphere), so that a plain mean of transmittances is
// the diffuse sky light a horizontal surface receives.
std::array<glm::vec3, CrownShade::kDirections> skyDirections() {
  std::array<glm::vec3, CrownShade::kDirections> directions;
  for (int i = 0; i < CrownShade::kDirections; ++i) {
    const float u = (i + 0.5f) / CrownShade::kDirections;
    float v = 0.0f;  // the radical inverse of i in base 2
    for (unsigned bits = static_cast<unsigned>(i), f = 1; bits; bits >>= 1, ++f)
      v += static_cast<float>(bits & 1u) / static_cast<float>(1u << f);
    const float r = std::sqrt(u), phi = 6.2831853f * v;
    directions[i] = glm::vec3(r * std::cos(phi), std::sqrt(1.0f - u), r * std::sin(phi));
  }
  return directions;
}

}  // namespace

CrownShade::CrownShade(const TreeSkeleton& tree, const Species& species) {
  if (tree.leaves.empty()) return;  // nothing shades: visibility 1 everywhere
  // A leaf counts at its blade's middle.
  auto middle = [](const Leaf& leaf) {
    return leaf.position + 0.5f * leaf.size_m * leaf.direction;
  };
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const Leaf& leaf : tree.leaves) {
    lo = glm::min(lo, middle(leaf));
    hi = glm::max(hi, middle(leaf));
  }
  const glm::vec3 extent = hi - lo;
  cell_m_ = std::max(std::max({extent.x, extent.y, extent.z}) / (kMaxCells - 1), 0.05f);
  size_ = glm::ivec3(glm::floor(extent / cell_m_)) + 1;
  origin_ = lo;

  // Leaf area density: each leaf's visible area in the cell holding its middle.
  std::vector<float> density(static_cast<std::size_t>(size_.x) * size_.y * size_.z, 0.0f);
  const float perVolume = 1.0f / (cell_m_ * cell_m_ * cell_m_);
  auto cellOf = [&](glm::vec3 p) {
    return glm::clamp(glm::ivec3(glm::floor((p - origin_) / cell_m_)), glm::ivec3(0), size_ - 1);
  };
  for (const Leaf& leaf : tree.leaves)
    density[indexOf(cellOf(middle(leaf)))] += visibleLeafArea(species, leaf.size_m) * perVolume;

  // Transmittance toward each sky direction from each cell centre, marching a cell at a time
  // (half of the own cell's leaves lie between its centre and the sky).
  const auto directions = skyDirections();
  visibility_.assign(density.size(), 1.0f);
  const glm::vec3 top = glm::vec3(size_) * cell_m_;
  tbb::parallel_for(0, size_.z, [&](int z) {
    for (int y = 0; y < size_.y; ++y)
      for (int x = 0; x < size_.x; ++x) {
        const glm::vec3 start = (glm::vec3(x, y, z) + 0.5f) * cell_m_;
        float sum = 0.0f;
        for (const glm::vec3& d : directions) {
          float leafArea = 0.5f * density[indexOf({x, y, z})];
          for (glm::vec3 p = start + d * cell_m_;
               glm::all(glm::greaterThanEqual(p, glm::vec3(0.0f))) &&
               glm::all(glm::lessThan(p, top));
               p += d * cell_m_)
            // (p below the top by less than a rounding error can still divide up to size_)
            leafArea += density[indexOf(glm::min(glm::ivec3(p / cell_m_), size_ - 1))];
          sum += std::exp(-kLeafProjection * leafArea * cell_m_);
        }
        visibility_[indexOf({x, y, z})] = sum / kDirections;
      }
  });
}

std::size_t CrownShade::indexOf(glm::ivec3 cell) const {
  return (static_cast<std::size_t>(cell.z) * size_.y + cell.y) * size_.x + cell.x;
}

float CrownShade::cellAt(int x, int y, int z) const {
  return visibility_[indexOf(glm::clamp(glm::ivec3(x, y, z), glm::ivec3(0), size_ - 1))];
}

float CrownShade::skyVisibility(glm::vec3 point) const {
  if (visibility_.empty()) return 1.0f;
  // Trilinear between cell centres; outside the grid, the nearest border cells' values.
  const glm::vec3 g = (point - origin_) / cell_m_ - 0.5f;
  const glm::vec3 f0 = glm::floor(g);
  const glm::vec3 t = glm::clamp(g - f0, 0.0f, 1.0f);
  const glm::ivec3 c(f0);
  auto lerp = [](float a, float b, float s) { return a + (b - a) * s; };
  const float x00 = lerp(cellAt(c.x, c.y, c.z), cellAt(c.x + 1, c.y, c.z), t.x);
  const float x10 = lerp(cellAt(c.x, c.y + 1, c.z), cellAt(c.x + 1, c.y + 1, c.z), t.x);
  const float x01 = lerp(cellAt(c.x, c.y, c.z + 1), cellAt(c.x + 1, c.y, c.z + 1), t.x);
  const float x11 = lerp(cellAt(c.x, c.y + 1, c.z + 1), cellAt(c.x + 1, c.y + 1, c.z + 1), t.x);
  return lerp(lerp(x00, x10, t.y), lerp(x01, x11, t.y), t.z);
}

void shadeVertices(WindMesh& mesh, const CrownShade& shade) {
  for (WindPart& part : mesh.parts)
    for (TreeVertex& v : part.vertices) v.skyVisibility = shade.skyVisibility(v.position);
}

}  // namespace eco
