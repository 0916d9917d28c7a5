#include "render/gl/scene_renderer.hpp"

#include <chrono>
#include <cmath>
#include <functional>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/frames.hpp"
#include "core/stopwatch.hpp"
#include "sim/grid.hpp"

namespace eco {
namespace {

// Clear air: a meteorological visibility of 100 km (Koschmieder: 3.9 / density) at the
// haze's base, the landscape's mean altitude, thinning upward with the scale height of the
// aerosols (1.2 km: Bruneton and Neyret 2008, after Nishita et al. 1993).
constexpr float kClearAirFogDensity = 3.9f / 100000.0f;
constexpr float kHazeScaleHeight_m = 1200.0f;

}  // namespace

SceneRenderer::SceneRenderer(const Terrain& terrain, double latitude_deg,
                             const TreeLibrary* library, const ImpostorSettings& impostors)
    : terrainData_(terrain),
      latitude_deg_(latitude_deg),
      hazeBase_m_(static_cast<float>(statsOf(terrain.height_m).mean)),
      terrain_(terrain),
      groundCover_(terrain),
      sky_({{GL_VERTEX_SHADER, "sky.vert"}, {GL_FRAGMENT_SHADER, "sky.frag"}}),
      skyArray_(makeVertexArray()) {
  if (library) forest_ = std::make_unique<ForestRenderer>(*library, impostors, uniforms_);
}

void SceneRenderer::reloadTrees(bool rebakeImpostors) {
  if (forest_) forest_->reloadMeshes(rebakeImpostors);
}

void SceneRenderer::renderShadowMaps(const RenderOptions& options, FrameUniforms u,
                                     const ShadowCascades& cascades, bool forestCasts,
                                     const std::function<void(RenderPass)>& endPass) {
  if (shadowSize_ != options.shadowMapSize) {
    shadowSize_ = options.shadowMapSize;
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &texture);
    shadowDepth_ = GlName(GlKind::Texture, texture);
    glTextureStorage3D(texture, 1, GL_DEPTH_COMPONENT32F, shadowSize_, shadowSize_,
                       kShadowCascades);
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(texture, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    GLuint framebuffer = 0;
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferDrawBuffer(framebuffer, GL_NONE);
    shadowFramebuffer_ = GlName(GlKind::Framebuffer, framebuffer);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, shadowFramebuffer_.id());
  glViewport(0, 0, shadowSize_, shadowSize_);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  for (int c = 0; c < kShadowCascades; ++c) {
    glNamedFramebufferTextureLayer(shadowFramebuffer_.id(), GL_DEPTH_ATTACHMENT, shadowDepth_.id(),
                                   0, c);
    glClear(GL_DEPTH_BUFFER_BIT);
    u.lightViewProj = cascades[c].lightViewProj;
    uniforms_.upload(u);
    terrain_.draw(Frustum::fromMatrix(u.lightViewProj), true);
    if (forestCasts) forest_->drawShadows(static_cast<std::size_t>(c));
    endPass(static_cast<RenderPass>(static_cast<int>(RenderPass::ShadowNear) + c));
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
}

FrameStats SceneRenderer::render(const Forest* forest, const Camera& camera,
                                 const RenderOptions& options, const RenderTarget& target,
                                 const ForestIndex* index) {
  const auto start = std::chrono::steady_clock::now();
  FrameStats stats;
  const Lighting light = lightingFor(latitude_deg_, options.sun);
  const float aspect = static_cast<float>(target.width) / static_cast<float>(target.height);

  const bool shadows = options.shadows && light.toSun.y > 0.02f;
  ShadowCascades cascades{};
  if (shadows)
    cascades = shadowCascades(camera, light.toSun, options.shadowReach, options.shadowMapSize);

  FrameUniforms u;
  const glm::mat4 viewProj = camera.projection(aspect) * camera.view();
  u.viewProj = viewProj;
  u.inverseViewProj = glm::inverse(viewProj);
  for (int c = 0; c < kShadowCascades; ++c) u.shadowCascades[c] = cascades[c].lightViewProj;
  u.camera = glm::vec4(camera.position, static_cast<float>(options.wind.time));
  u.toSun = glm::vec4(light.toSun, shadows ? 1.0f : 0.0f);
  u.sunColor = glm::vec4(light.sunColor, options.fogDensity.value_or(kClearAirFogDensity));
  u.skyZenith = glm::vec4(light.skyZenith, hazeBase_m_);
  u.skyHorizon = glm::vec4(light.skyHorizon, kHazeScaleHeight_m);
  u.ambient = glm::vec4(light.ambient, 0.0f);
  const glm::dvec3 toward = worldDownwindOf(options.wind.fromBearing_deg);
  const double directed = options.wind.directed_wg / kBendBasis_wg;
  u.wind =
      glm::vec4(static_cast<float>(toward.x * directed), static_cast<float>(toward.z * directed),
                static_cast<float>(options.wind.sway_ws / kSwayBasis_ws),
                static_cast<float>(options.wind.gust));

  if (forest_ && forest)
    stats.forest = forest_->prepare(
        *forest, camera, target.width, target.height, options.lod,
        shadows ? std::span<const ShadowBox>(cascades) : std::span<const ShadowBox>(), index);
  stats.prepareMs = millisecondsSince(start) - stats.forest.setupMs();

  // Where passes are timed, each is also counted in fragments shaded, where the GL counts
  // them (ARB_pipeline_statistics_query).
  const bool countFragments =
      options.timePasses && epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query");
  GlName fragmentQuery;
  if (countFragments) {
    GLuint query = 0;
    glGenQueries(1, &query);  // Mesa 22.3 refuses this target in glCreateQueries
    fragmentQuery = GlName(GlKind::Query, query);
  }
  if (options.timePasses) glFinish();  // the instances' upload is prepare's
  if (countFragments) glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, fragmentQuery.id());
  auto passStart = std::chrono::steady_clock::now();
  const auto endPass = [&](RenderPass pass) {
    if (!options.timePasses) return;
    glFinish();
    const int p = static_cast<int>(pass);
    stats.passMs[p] = millisecondsSince(passStart);
    if (countFragments) {
      glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
      GLuint64 fragments = 0;
      glGetQueryObjectui64v(fragmentQuery.id(), GL_QUERY_RESULT, &fragments);
      stats.passFragments[p] = fragments;
      if (pass != RenderPass::Impostors)
        glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, fragmentQuery.id());
    }
    passStart = std::chrono::steady_clock::now();
  };

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  if (shadows)
    renderShadowMaps(options, u, cascades,
                     forest_ && forest && stats.forest.shadowCasterCount() > 0, endPass);
  glBindTextureUnit(4, shadowDepth_.id());

  target.bind();
  glEnable(GL_FRAMEBUFFER_SRGB);
  uniforms_.upload(u);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  sky_.use();
  glBindVertexArray(skyArray_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthMask(GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  const Frustum frustum = Frustum::fromMatrix(viewProj);
  // The trees under LodSettings::minPixels are not drawn (unless a level is forced on every
  // tree): the ground shows their crowns.
  const float unresolvedPerMetre =
      options.lod.forcedLevel >= 0 ? 0.0f
                                   : options.lod.minPixels / camera.pixelsPerRadian(target.height);
  stats.terrainTriangles = terrain_.draw(frustum, false, unresolvedPerMetre);
  endPass(RenderPass::SkyAndTerrain);
  stats.groundTufts = groundCover_.draw(camera.position, frustum, options.groundCover);
  endPass(RenderPass::GroundCover);
  if (forest_ && forest) forest_->drawMeshes();
  endPass(RenderPass::TreeMeshes);
  if (forest_ && forest) forest_->drawSprites();
  endPass(RenderPass::Impostors);
  glFinish();
  checkGl("SceneRenderer::render");
  stats.frameMs = millisecondsSince(start) - stats.forest.setupMs();
  return stats;
}

void SceneRenderer::setForestFloor(const Forest& forest) {
  if (!forest_) return;
  setForestFloor(canopyFloor(forest, forest_->library(), terrainData_.grid));
}

void SceneRenderer::setForestFloor(const CanopyFloor& floor) {
  if (!forest_) return;
  Field cover = floor.cover();
  terrain_.setCanopyCover(cover);
  terrain_.setCanopyFloor(floor);
  groundCover_.cover().setCanopyCover(std::move(cover));
}

void SceneRenderer::setGroundMoisture(Field moisture) {
  terrain_.setMoisture(moisture);
  groundCover_.cover().setMoisture(std::move(moisture));
}

DrawFrame frameDrawer(SceneRenderer& renderer, FrameSize size, int samples) {
  auto target =
      std::make_shared<RenderTarget>(RenderTarget::create(size.width, size.height, 0, samples));
  return [&renderer, target](const FrameTrees& trees, const Camera& camera,
                             const RenderOptions& options) {
    renderer.setForestFloor(trees.floor);  // each frame's trees: the floor grows with them
    renderer.render(&trees.shown, camera, options, *target, trees.index);
    return readPixels(*target);
  };
}

}  // namespace eco
