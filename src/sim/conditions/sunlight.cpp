#include "sim/conditions/sunlight.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "core/angles.hpp"
#include "core/error.hpp"
#include "sim/embree_device.hpp"
#include "sim/terrain_mesh.hpp"

namespace eco {
struct TerrainScene::Impl {
  RTCScene scene = nullptr;
};

double solarDeclination(double dayOfYear) {
  return radians(23.44) * std::sin(2.0 * std::numbers::pi * (284.0 + dayOfYear) / 365.0);
}

glm::dvec3 sunDirection(double latitude_deg, double declination, double hourAngle) {
  const double phi = radians(latitude_deg);
  return glm::normalize(
      glm::dvec3(-std::cos(declination) * std::sin(hourAngle),
                 std::sin(declination) * std::cos(phi) -
                     std::cos(declination) * std::cos(hourAngle) * std::sin(phi),
                 std::sin(declination) * std::sin(phi) +
                     std::cos(declination) * std::cos(hourAngle) * std::cos(phi)));
}

SunPath makeSunPath(double latitude_deg, const SunlightSettings& settings) {
  SunPath path;
  const double phi = radians(latitude_deg);
  for (int d = 0; d < settings.days; ++d) {
    const double day = 365.0 * (d + 0.5) / settings.days;
    const double delta = solarDeclination(day);
    const double cosSunset = std::clamp(-std::tan(phi) * std::tan(delta), -1.0, 1.0);
    const double sunset = std::acos(cosSunset);  // hour angle, radians; 0 in polar night
    if (sunset <= 0.0) continue;
    const double step = 2.0 * sunset / settings.hoursPerDay;
    for (int h = 0; h < settings.hoursPerDay; ++h) {
      const double omega = -sunset + (h + 0.5) * step;
      const glm::dvec3 s = sunDirection(latitude_deg, delta, omega);
      if (s.z <= 0.0) continue;
      path.directions.push_back(s);
      path.weights.push_back(step);  // time the sample stands for, in radians of hour angle
    }
  }
  return path;
}

std::vector<glm::dvec3> skyDirections(int count) {
  std::vector<glm::dvec3> directions;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    double z = 1.0 - (i + 0.5) / count;  // uniform in z = uniform in solid angle
    double r = std::sqrt(1.0 - z * z);
    directions.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return directions;
}

glm::dvec3 planeNormal(double slope_deg, double aspect_deg) {
  const double s = radians(slope_deg), a = radians(aspect_deg);
  return {std::sin(s) * std::sin(a), std::sin(s) * std::cos(a), std::cos(s)};
}

double flatInsolation(const SunPath& sun) {
  double flat = 0.0;
  for (std::size_t i = 0; i < sun.directions.size(); ++i)
    flat += sun.weights[i] * sun.directions[i].z;
  return flat;
}

double unshadedDirectRatio(const SunPath& sun, glm::dvec3 normal) {
  double onPlane = 0.0;
  for (std::size_t i = 0; i < sun.directions.size(); ++i)
    onPlane += sun.weights[i] * std::max(0.0, glm::dot(normal, sun.directions[i]));
  const double flat = flatInsolation(sun);
  return flat > 0.0 ? onPlane / flat : 0.0;
}

TerrainScene::TerrainScene(const Terrain& terrain)
    : impl_(std::make_unique<Impl>()), terrain_(terrain) {
  const Grid& g = terrain.grid;
  EmbreeDevice& device = embree();
  RTCGeometry mesh = newTerrainGeometry(terrain);
  impl_->scene = rtcNewScene(device.device);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  rtcAttachGeometry(impl_->scene, mesh);
  rtcReleaseGeometry(mesh);
  rtcCommitScene(impl_->scene);
  device.check("building the terrain scene");
  maxHeight_m_ = *std::max_element(terrain.height_m.begin(), terrain.height_m.end());
  extent_m_ = static_cast<float>(std::hypot(g.width * g.dx_m, g.height * g.dy_m));
}

TerrainScene::~TerrainScene() {
  rtcReleaseScene(impl_->scene);
}

namespace {

RTCRay toEmbree(const TerrainScene::Ray& r) {
  RTCRay ray{};
  ray.org_x = r.origin.x, ray.org_y = r.origin.y, ray.org_z = r.origin.z;
  ray.dir_x = r.direction.x, ray.dir_y = r.direction.y, ray.dir_z = r.direction.z;
  ray.tnear = r.tnear;
  ray.tfar = r.tfar;
  ray.mask = 0xFFFFFFFFu;
  return ray;
}

}  // namespace

void TerrainScene::occluded(const std::vector<Ray>& rays,
                            std::vector<std::uint8_t>& blocked) const {
  thread_local std::vector<RTCRay> batch;
  batch.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) batch[i] = toEmbree(rays[i]);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcOccluded1M(impl_->scene, &context, batch.data(), static_cast<unsigned>(batch.size()),
                sizeof(RTCRay));
  blocked.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) blocked[i] = batch[i].tfar < 0.0f ? 1 : 0;
}

void TerrainScene::occludedOneByOne(const std::vector<Ray>& rays,
                                    std::vector<std::uint8_t>& blocked) const {
  blocked.resize(rays.size());
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    RTCRay ray = toEmbree(rays[i]);
    rtcOccluded1(impl_->scene, &context, &ray);
    blocked[i] = ray.tfar < 0.0f ? 1 : 0;
  }
}

std::vector<glm::dvec3> rowNormals(const Grid& g, const Field& slope_deg, const Field& aspect_deg,
                                   int y) {
  std::vector<glm::dvec3> normals(g.width);
  for (int x = 0; x < g.width; ++x)
    normals[x] = planeNormal(slope_deg[g.index(x, y)], std::max(0.0f, aspect_deg[g.index(x, y)]));
  return normals;
}

void rowRays(const TerrainScene& scene, int y, const std::vector<glm::dvec3>& normals,
             glm::dvec3 direction, std::vector<TerrainScene::Ray>& rays, std::vector<int>& cells) {
  rays.clear();
  cells.clear();
  const float cell = scene.cellSize();
  const float lift = 0.01f * cell, tnear = 0.25f * cell;
  for (int x = 0; x < static_cast<int>(normals.size()); ++x) {
    if (glm::dot(normals[x], direction) <= 0.0) continue;  // the slope faces away: self-shaded
    glm::vec3 origin = cellPosition(scene.terrain(), x, y) + glm::vec3(0.0f, 0.0f, lift);
    // Past the height where the rising ray clears the highest terrain nothing can block
    // it; the map's diagonal bounds near-horizontal rays.
    float clear = (scene.maxHeight() - origin.z + 1.0f) / static_cast<float>(direction.z);
    rays.push_back(
        {origin, glm::vec3(direction), tnear, std::min(std::max(clear, tnear), scene.extent())});
    cells.push_back(x);
  }
}

void computeSunniness(const Terrain& terrain, const Field& slope_deg, const Field& aspect_deg,
                      double latitude_deg, const SunlightSettings& settings, Field& sunniness,
                      SunlightParts* parts, const std::function<void(double)>& progress) {
  const Grid& g = terrain.grid;
  const SunPath sun = makeSunPath(latitude_deg, settings);
  const std::vector<glm::dvec3> sky = skyDirections(settings.skyDirections);
  const double flatDirect = flatInsolation(sun);
  double flatSky = 0.0;
  for (const glm::dvec3& d : sky) flatSky += d.z;
  const double f = settings.diffuseFraction;

  // The best unshaded slope: facing the equator, the tilt that gathers most light.
  double best = 1.0;
  for (int tilt = 0; tilt <= 90; ++tilt) {
    glm::dvec3 n = planeNormal(tilt, latitude_deg >= 0.0 ? 180.0 : 0.0);
    double skyShare = 0.0;
    for (const glm::dvec3& d : sky) skyShare += std::max(0.0, glm::dot(n, d));
    best = std::max(best, (1.0 - f) * unshadedDirectRatio(sun, n) + f * skyShare / flatSky);
  }

  TerrainScene scene(terrain);
  Field direct(g.cellCount(), 0.0f), skyView(g.cellCount(), 0.0f);
  std::atomic<std::uint64_t> rayCount{0};
  std::atomic<int> rowsDone{0};
  // One batch per row and direction: all cells of the row toward one direction, so that
  // neighbouring rays are coherent. Each cell's result depends only on its own rays, so
  // the fields are identical whatever the thread count.
  tbb::parallel_for(0, g.height, [&](int y) {
    std::vector<TerrainScene::Ray> rays;
    std::vector<int> cellOf;
    std::vector<std::uint8_t> blocked;
    std::vector<double> sumDirect(g.width, 0.0), sumSky(g.width, 0.0);
    const std::vector<glm::dvec3> normal = rowNormals(g, slope_deg, aspect_deg, y);
    auto cast = [&](const std::vector<glm::dvec3>& directions, auto&& accumulate) {
      for (std::size_t k = 0; k < directions.size(); ++k) {
        rowRays(scene, y, normal, directions[k], rays, cellOf);
        if (rays.empty()) continue;
        scene.occluded(rays, blocked);
        rayCount += rays.size();
        for (std::size_t r = 0; r < rays.size(); ++r)
          if (!blocked[r]) accumulate(k, cellOf[r]);
      }
    };
    cast(sun.directions, [&](std::size_t k, int x) {
      sumDirect[x] += sun.weights[k] * glm::dot(normal[x], sun.directions[k]);
    });
    cast(sky, [&](std::size_t k, int x) { sumSky[x] += glm::dot(normal[x], sky[k]); });
    for (int x = 0; x < g.width; ++x) {
      direct[g.index(x, y)] = static_cast<float>(sumDirect[x] / flatDirect);
      skyView[g.index(x, y)] = static_cast<float>(sumSky[x] / flatSky);
    }
    int done = ++rowsDone;
    if (progress) progress(static_cast<double>(done) / g.height);
  });
  embree().check("casting sun rays");

  sunniness.resize(g.cellCount());
  for (std::size_t c = 0; c < sunniness.size(); ++c)
    sunniness[c] =
        static_cast<float>(std::clamp(((1.0 - f) * direct[c] + f * skyView[c]) / best, 0.0, 1.0));
  if (parts) {
    parts->directRelative = std::move(direct);
    parts->skyView = std::move(skyView);
    parts->best = best;
    parts->rays = rayCount;
  }
}

}  // namespace eco
