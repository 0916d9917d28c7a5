#include "sim/ecology/canopy_light.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "sim/conditions/sunlight.hpp"
#include "sim/embree_device.hpp"

namespace eco {
namespace {

// Optical depth is summed in fixed point so that the order Embree meets the crowns in
// cannot change the last bit of the result (floating-point sums depend on order).
constexpr double kDepthUnit = 1e-7;
// Past this optical depth (transmittance below 0.1 %) a ray counts as blocked.
constexpr double kOpaqueDepth = 6.9;
// How far a light ray looks for crowns and terrain in the way.
constexpr float kReach_m = 150.0f;

// Rays are traced in packets of this many nearby probes sharing one direction, so that
// Embree walks the crown hierarchy once for all of them.
constexpr int kPacket = 4;
static_assert(kPacket == 4, "tracePacket traces an RTCRay4 with rtcOccluded4");

struct PacketQuery {
  RTCIntersectContext context;  // first member: Embree hands back a pointer to it
  const std::vector<Crown>* crowns;
  int self[kPacket];
  std::int64_t depth[kPacket];  // in kDepthUnit, per ray (the ray's id is its lane)
};

// The part of the ray [tnear, tfar] inside the ellipsoid, in metres (direction is unit).
float chordThrough(const Crown& c, glm::vec3 origin, glm::vec3 direction, float tnear, float tfar) {
  const glm::vec3 scale(1.0f / c.radius_m, 1.0f / c.radius_m, 1.0f / c.halfLength_m);
  const glm::vec3 o = (origin - c.centre) * scale, d = direction * scale;
  const float a = glm::dot(d, d), b = glm::dot(o, d), cc = glm::dot(o, o) - 1.0f;
  const float discriminant = b * b - a * cc;
  if (discriminant <= 0.0f) return 0.0f;
  const float root = std::sqrt(discriminant);
  const float t0 = std::max((-b - root) / a, tnear), t1 = std::min((-b + root) / a, tfar);
  return std::max(t1 - t0, 0.0f);
}

void crownBounds(const RTCBoundsFunctionArguments* args) {
  const auto& crowns = *static_cast<const std::vector<Crown>*>(args->geometryUserPtr);
  const Crown& c = crowns[args->primID];
  RTCBounds* b = args->bounds_o;
  b->lower_x = c.centre.x - c.radius_m, b->upper_x = c.centre.x + c.radius_m;
  b->lower_y = c.centre.y - c.radius_m, b->upper_y = c.centre.y + c.radius_m;
  b->lower_z = c.centre.z - c.halfLength_m, b->upper_z = c.centre.z + c.halfLength_m;
}

// Crowns never stop a ray by themselves: each one met adds its optical depth, and the ray
// ends (occluded) only when the sum passes kOpaqueDepth.
void crownOccluded(const RTCOccludedFunctionNArguments* args) {
  auto* query = reinterpret_cast<PacketQuery*>(args->context);
  const Crown& c = (*query->crowns)[args->primID];
  RTCRayN* ray = args->ray;
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (!args->valid[i]) continue;
    const unsigned lane = RTCRayN_id(ray, n, i);
    if (c.owner == query->self[lane]) continue;
    glm::vec3 origin(RTCRayN_org_x(ray, n, i), RTCRayN_org_y(ray, n, i), RTCRayN_org_z(ray, n, i));
    glm::vec3 direction(RTCRayN_dir_x(ray, n, i), RTCRayN_dir_y(ray, n, i),
                        RTCRayN_dir_z(ray, n, i));
    float& tfar = RTCRayN_tfar(ray, n, i);
    const float chord = chordThrough(c, origin, direction, RTCRayN_tnear(ray, n, i), tfar);
    if (chord <= 0.0f) continue;
    std::int64_t& depth = query->depth[lane];
    depth += std::llround(c.opticalDepthPerMetre * chord / kDepthUnit);
    if (depth * kDepthUnit > kOpaqueDepth) tfar = -std::numeric_limits<float>::infinity();
  }
}

void crownIntersect(const RTCIntersectFunctionNArguments*) {}  // only occlusion is asked

// Interleaves the bits of x and y in metres (16 bits each, wrapping past 65 km).
std::uint64_t mortonCode(glm::vec3 point) {
  auto spread = [](std::uint64_t v) {
    v &= 0xFFFF;
    v = (v | (v << 8)) & 0x00FF00FF;
    v = (v | (v << 4)) & 0x0F0F0F0F;
    v = (v | (v << 2)) & 0x33333333;
    v = (v | (v << 1)) & 0x55555555;
    return v;
  };
  const auto x = static_cast<std::uint64_t>(std::max(point.x, 0.0f));
  const auto y = static_cast<std::uint64_t>(std::max(point.y, 0.0f));
  return spread(x) | (spread(y) << 1);
}

}  // namespace

LightDirections makeLightDirections(double latitude_deg, int count, double diffuseFraction) {
  // A Fibonacci lattice spread evenly in cosine-weighted solid angle: each direction brings
  // the same share of diffuse light, and none wastes rays near the horizon.
  LightDirections light;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = std::sqrt(1.0 - (i + 0.5) / count), r = std::sqrt(1.0 - z * z);
    light.direction.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    light.weight.push_back(diffuseFraction / count);
  }
  SunlightSettings settings;
  const SunPath sun = makeSunPath(latitude_deg, settings);
  const double flat = flatInsolation(sun);
  for (std::size_t s = 0; s < sun.directions.size(); ++s) {
    std::size_t nearest = 0;
    for (std::size_t k = 1; k < light.direction.size(); ++k)
      if (glm::dot(sun.directions[s], light.direction[k]) >
          glm::dot(sun.directions[s], light.direction[nearest]))
        nearest = k;
    light.weight[nearest] += (1.0 - diffuseFraction) * sun.weights[s] * sun.directions[s].z / flat;
  }
  return light;
}

struct CanopyScene::Impl {
  RTCScene scene = nullptr;
  unsigned crownGeometry = RTC_INVALID_GEOMETRY_ID;
};

CanopyScene::CanopyScene(const Terrain& terrain) : impl_(std::make_unique<Impl>()) {
  EmbreeDevice& device = embree();
  RTCGeometry mesh = newTerrainGeometry(terrain);
  // Dynamic: the terrain keeps its own BVH while the crowns are replaced every year.
  impl_->scene = rtcNewScene(device.device);
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_DYNAMIC);
  rtcAttachGeometry(impl_->scene, mesh);
  rtcReleaseGeometry(mesh);
  rtcCommitScene(impl_->scene);
  device.check("building the terrain scene");
  maxTerrain_m_ = *std::max_element(terrain.height_m.begin(), terrain.height_m.end());
  maxCrownTop_m_ = maxTerrain_m_;
}

CanopyScene::~CanopyScene() {
  rtcReleaseScene(impl_->scene);
}

void CanopyScene::setCrowns(std::vector<Crown> crowns) {
  EmbreeDevice& device = embree();
  if (impl_->crownGeometry != RTC_INVALID_GEOMETRY_ID) {
    rtcDetachGeometry(impl_->scene, impl_->crownGeometry);
    impl_->crownGeometry = RTC_INVALID_GEOMETRY_ID;
  }
  crowns_ = std::move(crowns);
  maxCrownTop_m_ = maxTerrain_m_;
  for (const Crown& c : crowns_)
    maxCrownTop_m_ = std::max(maxCrownTop_m_, c.centre.z + c.halfLength_m);
  if (!crowns_.empty()) {
    RTCGeometry geometry = rtcNewGeometry(device.device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(crowns_.size()));
    rtcSetGeometryUserData(geometry, &crowns_);
    rtcSetGeometryBoundsFunction(geometry, crownBounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, crownIntersect);
    rtcSetGeometryOccludedFunction(geometry, crownOccluded);
    rtcCommitGeometry(geometry);
    impl_->crownGeometry = rtcAttachGeometry(impl_->scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(impl_->scene);
  device.check("building the crown scene");
}

double CanopyScene::lightAt(glm::vec3 point, int self, const LightDirections& sky) const {
  const LightProbe probe{point, self};
  const LightProbe* probes[] = {&probe};
  float light = 0.0f;
  tracePacket(probes, 1, sky, &light);
  return light;
}

std::vector<float> CanopyScene::lightAt(const std::vector<LightProbe>& probes,
                                        const LightDirections& sky) const {
  // Packets of probes that are close together (in Morton order of 1 m squares) share most
  // of their way through the crown hierarchy.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> order(probes.size());
  for (std::size_t i = 0; i < probes.size(); ++i)
    order[i] = {mortonCode(probes[i].point), static_cast<std::uint32_t>(i)};
  std::sort(order.begin(), order.end());
  std::vector<float> light(probes.size());
  const std::size_t packets = (probes.size() + kPacket - 1) / kPacket;
  tbb::parallel_for(std::size_t{0}, packets, [&](std::size_t packet) {
    const std::size_t begin = packet * kPacket;
    const int count = static_cast<int>(std::min<std::size_t>(kPacket, probes.size() - begin));
    const LightProbe* members[kPacket];
    float result[kPacket];
    for (int lane = 0; lane < count; ++lane) members[lane] = &probes[order[begin + lane].second];
    tracePacket(members, count, sky, result);
    for (int lane = 0; lane < count; ++lane) light[order[begin + lane].second] = result[lane];
  });
  return light;
}

void CanopyScene::tracePacket(const LightProbe* const* probes, int count,
                              const LightDirections& sky, float* light) const {
  double sum[kPacket] = {};
  for (std::size_t k = 0; k < sky.direction.size(); ++k) {
    if (sky.weight[k] <= 0.0) continue;
    const glm::vec3 direction(sky.direction[k]);
    PacketQuery query;
    rtcInitIntersectContext(&query.context);
    query.crowns = &crowns_;
    RTCRay4 rays{};
    alignas(64) int valid[kPacket] = {};
    for (int lane = 0; lane < count; ++lane) {
      const glm::vec3 p = probes[lane]->point;
      query.self[lane] = probes[lane]->self;
      query.depth[lane] = 0;
      rays.org_x[lane] = p.x, rays.org_y[lane] = p.y, rays.org_z[lane] = p.z;
      rays.dir_x[lane] = direction.x, rays.dir_y[lane] = direction.y;
      rays.dir_z[lane] = direction.z;
      rays.tnear[lane] = 0.0f;
      // Beyond the height of the highest crown top nothing can be in the way, and the far
      // horizon is the sunniness field's business.
      rays.tfar[lane] = std::min((maxCrownTop_m_ + 1.0f - p.z) / direction.z, kReach_m);
      rays.mask[lane] = 0xFFFFFFFFu;
      rays.id[lane] = static_cast<unsigned>(lane);
      valid[lane] = rays.tfar[lane] > 0.0f ? -1 : 0;
    }
    rtcOccluded4(valid, impl_->scene, &query.context, &rays);
    for (int lane = 0; lane < count; ++lane) {
      if (!valid[lane]) {
        sum[lane] += sky.weight[k];          // above every crown and hill
      } else if (rays.tfar[lane] >= 0.0f) {  // not stopped by terrain or dense crowns
        sum[lane] += sky.weight[k] * std::exp(-static_cast<double>(query.depth[lane]) * kDepthUnit);
      }
    }
  }
  for (int lane = 0; lane < count; ++lane) light[lane] = static_cast<float>(sum[lane]);
}

}  // namespace eco
