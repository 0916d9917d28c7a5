#include "render/gl/forest_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/packing.hpp>

#include "core/image_metrics.hpp"
#include "gl_support.hpp"
#include "render/gl/frame_uniforms.hpp"
#include "render/gl/scene_renderer.hpp"
#include "render/gl/shader.hpp"
#include "render/scene/impostor.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// Toward a sun 17 degrees up in the south (world z is south).
const glm::vec3 kLowSouthernSun = glm::normalize(glm::vec3(0.0f, 0.3f, 1.0f));

// A row of mature maples northward from the camera, one every 20 m, and one behind it.
Forest rowOfTrees(const TreeLibrary& library, int count) {
  Forest forest;
  const int type = library.typeIndex(1, 0, 1);
  const float height = library.type(type).height_m;
  for (int i = 0; i < count; ++i)
    forest.add(library, type, worldFromMap(160, 26 + 20 * i, 100), height, 0.0f, 1.0f, i);
  forest.add(library, type, worldFromMap(160, 0, 100), height, 0.0f, 1.0f, 99);
  return forest;
}

TEST(ForestRenderer, CullsTreesOutsideTheViewAndCoarsensWithDistance) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(65, 10.0);
  FrameUniformBuffer uniforms;
  ForestRenderer renderer(library, {}, uniforms);
  const Forest forest = rowOfTrees(library, 30);
  Camera camera;
  camera.position = worldFromMap(160, 20, 105);  // looking north along the row
  const ForestStats stats = renderer.prepare(forest, camera, 640, 360, {}, {});
  EXPECT_EQ(stats.culled, 1u);  // the tree behind
  std::size_t drawn = 0;
  for (std::size_t n : stats.instances) drawn += n;
  EXPECT_GE(drawn, 30u);  // each tree at least once; cross-fading ones twice
  EXPECT_GT(stats.instances[0], 0u);
  EXPECT_GT(stats.instances[kLevelImpostor], 0u);
  EXPECT_LT(stats.triangles, stats.lod0Triangles);

  LodSettings allLod0;
  allLod0.forcedLevel = 0;
  const ForestStats lod0 = renderer.prepare(forest, camera, 640, 360, allLod0, {});
  EXPECT_EQ(lod0.instances[0], 30u);
  EXPECT_EQ(lod0.triangles, lod0.lod0Triangles);
  EXPECT_EQ(lod0.triangles, 30u * library.type(forest.type[0]).meshes.lods[0].triangleCount());
}

// The row of trees seen from the camera at its south end, for the shadow casters' tests.
struct HeadlessGl {
  HeadlessGl() { test::useHeadlessGl(); }  // before the renderer below is made
};
class ShadowCasting : public ::testing::Test, HeadlessGl {
 protected:
  ShadowCasting() { camera.position = worldFromMap(160, 20, 105); }
  // A square over the whole row, lit from `toSun`, whose map has this many texels a metre.
  static ShadowBox coveringTheRow(float mapPixelsPerMetre, glm::vec3 toSun) {
    ShadowBox box = shadowBox(worldFromMap(160, 300, 100), 1000.0f, toSun, 2048);
    box.mapPixelsPerMetre = mapPixelsPerMetre;
    return box;
  }

  const TreeLibrary& library = test::smallLibrary();
  FrameUniformBuffer uniforms;
  ForestRenderer renderer{library, {}, uniforms};
  const Forest forest = rowOfTrees(library, 30);
  Camera camera;
};

// The trees cast into a map whose points their shadows may fall on: under a sun overhead,
// those within the map's 75 m (1.5 times the square's half side, plus the crown) of north
// 60, one every 20 m from north 26 up to 126; the one behind the camera shades no point in
// view.
TEST_F(ShadowCasting, OnlyTreesInTheShadowBoxCastShadows) {
  const ShadowBox box = shadowBox(worldFromMap(160, 60, 100), 50.0f, {0.0f, 1.0f, 0.0f}, 600);
  const ForestStats stats = renderer.prepare(forest, camera, 640, 360, {}, {&box, 1});
  EXPECT_EQ(stats.shadowCasterCount(), 6u);
}

// Every tree standing over a map's points casts into it, out to the map's edge beyond the
// square (until this stop, trees were chosen by the square, and the points between the
// square and the map's edge lost their trees' shadows). A tree 70 m from the square's
// centre, under a sun overhead, casts into the map of a 50 m square; one 85 m away does not.
TEST_F(ShadowCasting, TreesCastIntoTheMapOutToItsEdgeBeyondTheSquare) {
  const ShadowBox box = shadowBox(worldFromMap(160, 60, 100), 50.0f, {0.0f, 1.0f, 0.0f}, 600);
  const TreeType& type = library.type(forest.type[0]);
  auto casts = [&](float north) {
    Forest one;
    one.add(library, forest.type[0], worldFromMap(160, north, 100), type.height_m, 0.0f, 1.0f, 1);
    return renderer.prepare(one, camera, 640, 360, {}, {&box, 1}).shadowCasterCount();
  };
  EXPECT_EQ(casts(60.0f + 70.0f), 1u);
  EXPECT_EQ(casts(60.0f + 75.0f + type.bounds.w + 1.0f), 0u);
}

// A tree's shadow has the gaps of the crown the viewer sees: in the nearest cascade it casts
// with the level it is drawn at, not with a smooth crown hull; a tree outside the view, and
// every tree in a coarser cascade, casts as an impostor.
TEST_F(ShadowCasting, TreesCastWithTheLevelTheyAreDrawnAtInTheNearestCascade) {
  // A low sun in the south: the tree behind the camera throws its shadow into the view.
  const ShadowBox everything = coveringTheRow(1.0f, kLowSouthernSun);
  const ShadowBox near = shadowBox(worldFromMap(160, 60, 100), 50.0f, kLowSouthernSun, 2048);
  const std::array<ShadowBox, 2> cascades{near, everything};
  for (int level = 0; level < kLevelCount; ++level) {
    LodSettings lod;
    lod.forcedLevel = level;
    const ForestStats stats = renderer.prepare(forest, camera, 640, 360, lod, cascades);
    // In the nearest, the trees in view that reach its map at their level, the one behind
    // as a sprite; every tree whose shadow the nearest does not hold in the other, as a
    // sprite.
    std::array<std::size_t, kLevelCount> expected{};
    std::size_t inNearest = 0;
    for (std::size_t i = 0; i < forest.size(); ++i) {
      const TreeType& type = library.type(forest.type[i]);
      const glm::vec3 centre = forest.position[i] + glm::vec3(type.bounds);  // yaw 0, scale 1
      const bool inView = i + 1 < forest.size();  // the last is behind the camera
      const MapHolds held = shadowHeldBy(near, centre, type.bounds.w);
      if (held != MapHolds::none) {
        ++expected[inView ? level : kLevelImpostor];
        ++inNearest;
        if (held == MapHolds::all) continue;
      }
      ++expected[kLevelImpostor];
    }
    ASSERT_GT(inNearest, 2u);
    for (int caster = 0; caster < kLevelCount; ++caster)
      EXPECT_EQ(stats.shadowCasters[caster], expected[caster]) << "drawn at " << level;
  }
  // Chosen by size: each level's casters are the trees drawn at it.
  const ForestStats bySize = renderer.prepare(forest, camera, 640, 360, {}, {&everything, 1});
  EXPECT_GT(bySize.shadowCasters[0], 0u);
  EXPECT_GT(bySize.shadowCasters[kLevelImpostor], 1u);
  EXPECT_EQ(bySize.shadowCasterCount(), 31u);
}

// Trees outside the view cast only where their shadow can reach it: the tree behind the
// camera casts under a low sun behind it, not under a sun ahead.
TEST_F(ShadowCasting, ATreeOutOfViewCastsOnlyWhereItsShadowCanReachTheView) {
  ShadowBox box = coveringTheRow(1.0f, kLowSouthernSun);
  EXPECT_EQ(renderer.prepare(forest, camera, 640, 360, {}, {&box, 1}).shadowCasterCount(), 31u);
  box.toSun = glm::vec3(1.0f, 1.0f, -1.0f) * kLowSouthernSun;  // the same sun in the north
  EXPECT_EQ(renderer.prepare(forest, camera, 640, 360, {}, {&box, 1}).shadowCasterCount(), 30u);
}

// A cascade's texels decide who casts there: a tree shorter than one texel casts nothing.
TEST_F(ShadowCasting, TreesSmallerThanACascadesTexelCastNothingThere) {
  const float height = library.type(forest.type[0]).height_m;
  const ShadowBox fine = coveringTheRow(1.01f / height, kLowSouthernSun);
  const ShadowBox coarse = coveringTheRow(0.99f / height, kLowSouthernSun);
  EXPECT_EQ(renderer.prepare(forest, camera, 640, 360, {}, {&fine, 1}).shadowCasterCount(), 31u);
  EXPECT_EQ(renderer.prepare(forest, camera, 640, 360, {}, {&coarse, 1}).shadowCasterCount(), 0u);
}

// A tree whose shadow a finer map holds whole casts into no coarser map: every point it can
// shadow reads the finer one. The row's cascades from its camera, 30 m to 600 m squares:
// the trees in the nearest map cast once, the rest into each map that reaches them.
TEST_F(ShadowCasting, ATreeWhoseShadowAFinerMapHoldsCastsIntoNoCoarserOne) {
  LodSettings impostors;
  impostors.forcedLevel = kLevelImpostor;
  const ShadowCascades cascades = shadowCascades(camera, kLowSouthernSun, {30.0f, 600.0f}, 2048);
  const ForestStats stats = renderer.prepare(forest, camera, 640, 360, impostors, cascades);
  std::size_t expected = 0;
  for (std::size_t i = 0; i < forest.size(); ++i) {
    const TreeType& type = library.type(forest.type[i]);
    const glm::vec3 centre = forest.position[i] + glm::vec3(type.bounds);  // yaw 0, scale 1
    for (const ShadowBox& box : cascades) {
      const MapHolds held = shadowHeldBy(box, centre, type.bounds.w);
      if (held == MapHolds::none) continue;
      ++expected;
      if (held == MapHolds::all) break;
    }
  }
  EXPECT_EQ(stats.shadowCasterCount(), expected);
  // Some trees are held by a finer map, so fewer cast than the maps they reach.
  std::size_t inMaps = 0;
  for (std::size_t i = 0; i < forest.size(); ++i)
    for (const ShadowBox& box : cascades)
      inMaps +=
          shadowHeldBy(box, forest.position[i] + glm::vec3(library.type(forest.type[i]).bounds),
                       library.type(forest.type[i]).bounds.w) != MapHolds::none;
  EXPECT_LT(stats.shadowCasterCount(), inMaps);
}

TEST(ForestRenderer, BlendingTreesDrawBothTypesAndAbsentTreesNothing) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  FrameUniformBuffer uniforms;
  ForestRenderer renderer(library, {}, uniforms);
  Forest forest = rowOfTrees(library, 3);
  Camera camera;
  camera.position = worldFromMap(160, 20, 105);
  LodSettings lod;
  lod.forcedLevel = 1;
  const auto drawn = [&] {
    const ForestStats stats = renderer.prepare(forest, camera, 640, 360, lod, {});
    return stats.instances[1];
  };
  EXPECT_EQ(drawn(), 3u);
  forest.blendType[0] = library.typeIndex(1, 0, 0);
  forest.blendWeight[0] = 0.4f;
  EXPECT_EQ(drawn(), 4u);  // the first tree as both age classes
  forest.presence[1] = 0.0f;
  EXPECT_EQ(drawn(), 3u);  // the second not at all
}

// A tree at presence p keeps about p of its pixels (dithered), whichever level draws it.
TEST(ForestRenderer, PresenceKeepsThatShareOfTheTreesPixels) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  SceneRenderer scene(terrain, 46.0, &library);
  Forest forest;
  const int type = library.typeIndex(1, 0, 1);
  forest.add(library, type, worldFromMap(160, 160, 100), library.type(type).height_m, 0.0f, 1.0f,
             1);
  Camera camera;
  camera.position = worldFromMap(160, 140, 100 + 0.5 * library.type(type).height_m);
  RenderOptions options;
  options.shadows = false;
  const RenderTarget target = RenderTarget::create(96, 96);
  auto treePixels = [&](float presence) {
    Forest empty;
    scene.render(&empty, camera, options, target);
    const Image background = readPixels(96, 96);
    forest.presence[0] = presence;
    scene.render(&forest, camera, options, target);
    return test::compareImages(readPixels(96, 96), background).differingShare;
  };
  const double full = treePixels(1.0f);
  ASSERT_GT(full, 0.05);
  EXPECT_NEAR(treePixels(0.5f) / full, 0.5, 0.1);
  EXPECT_EQ(treePixels(0.0f), 0.0);
}

TEST(ForestRenderer, VariantsShareTheImpostorOfTheirSpeciesAndAgeClass) {
  test::useHeadlessGl();
  const TreeLibrary library({test::namedLibrarySpecies("shrub")},
                            LibrarySettings{.variants = 3, .ageClasses = {0.3, 1.0}});
  FrameUniformBuffer uniforms;
  ForestRenderer renderer(library, {}, uniforms);
  for (int v = 0; v < 3; ++v)
    for (int a = 0; a < 2; ++a)
      EXPECT_EQ(renderer.impostorSource(library.typeIndex(0, v, a)), library.typeIndex(0, 0, a));
}

// A level is uploaded when a frame first draws a type at it, and an atlas is baked when a
// frame first draws its type's impostor source as a sprite (the variants share their first
// one's), once, from the source's level bakeLod; a tree drawn as a mesh needs no atlas.
TEST(ForestRenderer, UploadsLevelsAndBakesOneAtlasPerImpostorSourceWhenAFrameFirstDrawsThem) {
  test::useHeadlessGl();
  const TreeLibrary library({test::namedLibrarySpecies("shrub")},
                            LibrarySettings{.variants = 3, .ageClasses = {0.3, 1.0}});
  FrameUniformBuffer uniforms;
  const ImpostorSettings impostors;
  ForestRenderer renderer(library, impostors, uniforms);
  auto levelBytes = [&](int type, int level) {
    std::size_t bytes = 0;
    for (const WindPart& part : library.type(type).meshes.lods[level].parts)
      bytes += part.vertices.size() * sizeof(PackedTreeVertex) + part.indices.size() * 4;
    return bytes;
  };
  EXPECT_EQ(renderer.gpuMemory().meshBytes, 0u) << "nothing uploaded before a frame";
  EXPECT_EQ(renderer.gpuMemory().impostorBytes, 0u) << "nothing baked before a frame";
  // One atlas of albedo, normal and depth (RGBA8, mips add a third) per age class drawn.
  const std::size_t side = static_cast<std::size_t>(impostors.frames * impostors.tilePixels);
  const std::size_t atlas = 3 * 4 * side * side * 4 / 3;
  Camera camera;
  camera.position = worldFromMap(160, 20, 105);  // looking north at the trees
  auto forestOf = [&](std::initializer_list<int> types) {
    Forest forest;
    for (const int type : types)
      forest.add(library, type, worldFromMap(160, 60, 100), library.type(type).height_m, 0.0f, 1.0f,
                 1);
    return forest;
  };
  auto frameAt = [&](const Forest& forest, int level) {
    LodSettings lod;
    lod.forcedLevel = level;
    return renderer.prepare(forest, camera, 640, 360, lod, {});
  };
  const int first = library.typeIndex(0, 1, 0), second = library.typeIndex(0, 2, 0);
  const int youngSource = library.typeIndex(0, 0, 0), oldSource = library.typeIndex(0, 0, 1);
  const Forest young = forestOf({first, second});
  const ForestStats firstFrame = frameAt(young, 1);
  EXPECT_EQ(firstFrame.impostorBakeMs, 0.0) << "meshes need no atlas";
  EXPECT_GT(firstFrame.meshUploadMs, 0.0);
  EXPECT_EQ(renderer.gpuMemory().impostorBytes, 0u);
  std::size_t meshBytes = levelBytes(first, 1) + levelBytes(second, 1);
  EXPECT_EQ(renderer.gpuMemory().meshBytes, meshBytes) << "the level drawn, of the types drawn";
  EXPECT_EQ(frameAt(young, 1).meshUploadMs, 0.0);
  EXPECT_EQ(renderer.gpuMemory().meshBytes, meshBytes) << "uploaded once";
  // Two variants of the young class as sprites: one atlas, their source's, baked once.
  EXPECT_GT(frameAt(young, kLevelImpostor).impostorBakeMs, 0.0);
  EXPECT_EQ(renderer.gpuMemory().impostorBytes, atlas);
  meshBytes += levelBytes(youngSource, impostors.bakeLod);
  EXPECT_EQ(renderer.gpuMemory().meshBytes, meshBytes) << "the source's level it is baked from";
  EXPECT_EQ(frameAt(young, kLevelImpostor).impostorBakeMs, 0.0);
  // A young tree blending into the old class draws both: the old one's atlas too.
  Forest blending = forestOf({youngSource});
  blending.blendType[0] = oldSource;
  blending.blendWeight[0] = 0.5f;
  EXPECT_GT(frameAt(blending, kLevelImpostor).impostorBakeMs, 0.0);
  EXPECT_EQ(renderer.gpuMemory().impostorBytes, 2 * atlas);
  EXPECT_EQ(renderer.gpuMemory().meshBytes, meshBytes + levelBytes(oldSource, impostors.bakeLod));
  // The meshes changed: they are uploaded again, and the atlases dropped and baked again, as
  // frames draw them.
  renderer.reloadMeshes(true);
  EXPECT_EQ(renderer.gpuMemory().meshBytes, 0u);
  EXPECT_EQ(renderer.gpuMemory().impostorBytes, 0u);
  EXPECT_GT(frameAt(blending, kLevelImpostor).impostorBakeMs, 0.0);
  EXPECT_EQ(renderer.gpuMemory().impostorBytes, 2 * atlas);
  EXPECT_EQ(renderer.gpuMemory().meshBytes,
            levelBytes(youngSource, impostors.bakeLod) + levelBytes(oldSource, impostors.bakeLod));
}

TEST(ForestRenderer, PackedVerticesKeepPositionsExactlyAndTheRestClosely) {
  TreeVertex v{{1.25f, 20.5f, -3.0f}, glm::normalize(glm::vec3(0.3f, 0.9f, -0.2f)),
               {0.5f, 12.75f},        {0.01f, -0.2f, 0.3f},
               {1.5f, 0.0f, -0.75f},  {0.002f, 0.0f, 0.0f},
               {0.0f, 0.0f, 0.6f},    0.37f};
  const PackedTreeVertex p = packVertex(v);
  EXPECT_EQ(p.position, v.position);
  EXPECT_EQ(p.uv, v.uv);
  const glm::vec4 normal = glm::unpackSnorm3x10_1x2(p.normal);
  EXPECT_LT(glm::distance(glm::vec3(normal), v.normal), 2e-3f);
  EXPECT_NEAR(glm::unpackHalf1x16(p.wind[1]), -0.2f, 1e-4f);
  EXPECT_NEAR(glm::unpackHalf1x16(p.wind[3]), 1.5f, 1e-3f);
  EXPECT_NEAR(glm::unpackHalf1x16(p.wind[11]), 0.6f, 1e-3f);
  EXPECT_NEAR(glm::unpackUnorm1x16(p.skyVisibility), 0.37f, 1e-4f);
}

// One mature maple on flat ground, and a camera level with its middle, from the south, that
// sees it `pixels` tall in a picture twice that size (the tree fills half its height).
struct LoneMaple {
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(33, 10.0);
  Forest forest;
  float height_m = 0.0f;

  // `widthRatio`: its crown as wide as its type's times this (0.7 to 1.4, Forest::place).
  explicit LoneMaple(float widthRatio = 1.0f) {
    const int type = library.typeIndex(1, 0, 1);
    height_m = library.type(type).height_m;
    forest.add(library, type, worldFromMap(160, 160, 100), height_m,
               widthRatio * library.typeCrownRadius_m(type), 1.0f, 1);
  }
  static int pictureSize(float pixels) { return static_cast<int>(2.0f * pixels); }
  Camera seenAt(float pixels) const {
    Camera camera;
    const float distance = height_m * camera.pixelsPerRadian(pictureSize(pixels)) / pixels;
    camera.position = worldFromMap(160, 160 - distance, 100 + 0.5 * height_m);
    return camera;
  }
};

// Whether the pixel at byte `p` shows a tree: where the image differs from the empty scene.
bool isTreePixel(const Image& image, const Image& background, std::size_t p) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(image.rgba[p + c]) - int(background.rgba[p + c])) > 8) return true;
  return false;
}

// The trees' pixels, with their mean colour.
std::size_t treePixels(const Image& image, const Image& background,
                       glm::dvec3* meanColor = nullptr) {
  std::size_t count = 0;
  glm::dvec3 sum(0.0);
  for (std::size_t p = 0; p < image.rgba.size(); p += 4) {
    if (!isTreePixel(image, background, p)) continue;
    ++count;
    sum += glm::dvec3(image.rgba[p], image.rgba[p + 1], image.rgba[p + 2]);
  }
  if (meanColor) *meanColor = sum / std::max<double>(count, 1.0);
  return count;
}

// A forest drawn from one camera into a square picture without shadows, each time at a
// level forced on every tree, beside the empty scene drawn first: the background that tells
// a tree's pixels (treePixels).
class PicturesAtLevels {
 public:
  PicturesAtLevels(SceneRenderer& renderer, const Forest& forest, const Camera& camera, int size)
      : renderer_(renderer),
        forest_(forest),
        camera_(camera),
        size_(size),
        target_(RenderTarget::create(size, size)) {
    options_.shadows = false;
    Forest empty;
    renderer_.render(&empty, camera_, options_, target_);
    background_ = readPixels(size_, size_);
  }
  Image at(int level) {
    options_.lod.forcedLevel = level;
    renderer_.render(&forest_, camera_, options_, target_);
    return readPixels(size_, size_);
  }
  double treePixelsAt(int level) { return static_cast<double>(treePixels(at(level), background_)); }
  const Image& background() const { return background_; }

 private:
  SceneRenderer& renderer_;
  const Forest& forest_;
  Camera camera_;
  int size_;
  RenderTarget target_;
  RenderOptions options_;
  Image background_;
};

// At its switching size the impostor stands in for the meshes: the mature maple rendered at
// that size as LOD0 and as its impostor, compared as a whole, since single leaves fall
// on different pixels. Tolerances: the two cover the same number of pixels to within 20 %
// (leaf cards flicker in and out at this size), and their mean colours over the tree differ
// by less than 20 of 255 (RMS over the channels; the impostor shows its frames from up to
// 11 degrees off, out of 64-pixel tiles).
// At each quality's switching size to impostors (balanced 150 px, high 40 px), drawn with
// the impostors that quality bakes, the impostor covers the mesh's pixels to within 20 %
// and their mean colours differ by less than 20 of 255. Measured: 10.1 and 10.7 (the
// impostor a little lighter; 16.9 and 20.2 when shade() read a short mean normal as leaves
// facing every way of the sphere).
TEST(Impostor, MatchesTheMeshAtEachQualitysSwitchingSize) {
  test::useHeadlessGl();
  const LoneMaple maple;
  const Forest& forest = maple.forest;
  for (RenderQuality quality : {RenderQuality::Balanced, RenderQuality::High}) {
    SCOPED_TRACE(std::string(toString(quality)));
    SceneRenderer renderer(maple.terrain, 46.0, &maple.library, impostorSettingsFor(quality));
    const float switchPixels = switchPixelsFor(quality)[2];
    PicturesAtLevels pictures(renderer, forest, maple.seenAt(switchPixels),
                              LoneMaple::pictureSize(switchPixels));
    const Image mesh = pictures.at(0), impostor = pictures.at(kLevelImpostor);

    glm::dvec3 meshColor, impostorColor;
    const std::size_t meshPixels = treePixels(mesh, pictures.background(), &meshColor);
    const std::size_t impostorPixels = treePixels(impostor, pictures.background(), &impostorColor);
    ASSERT_GT(meshPixels, static_cast<std::size_t>(0.05 * switchPixels * switchPixels));
    const double coverageDifference =
        std::abs(double(meshPixels) - double(impostorPixels)) / double(meshPixels);
    EXPECT_LT(coverageDifference, 0.20) << meshPixels << " vs " << impostorPixels;
    const double colorDifference = glm::length(meshColor - impostorColor) / std::sqrt(3.0);
    EXPECT_LT(colorDifference, 20.0)
        << "mesh " << meshColor.r << "," << meshColor.g << "," << meshColor.b << " impostor "
        << impostorColor.r << "," << impostorColor.g << "," << impostorColor.b;
  }
}

// A sprite cropped to what its frames reach (ImpostorSettings::cropSprites) draws the
// picture of the bounding sphere's square, shadows included, from fewer fragments: a row of
// maples as impostors, seen from above and lit by the noon sun. What differs: pixels shaded
// a few levels apart (the sprite's pixels found from another size), and a few speckles of
// the square's edges, where bilinear filtering of the coarse mip levels read the
// neighbouring frame. Measured: the colour pass shades 0.95 times the fragments and the
// trees' shadows 0.59 times; 4 pixels of 102,400 differ by more than 10 (sum of channels).
TEST(Impostor, ACroppedSpriteDrawsTheSamePictureFromFewerFragments) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(65, 10.0);
  const Forest forest = rowOfTrees(library, 12), none;
  Camera camera;
  camera.position = worldFromMap(160, -10, 150);
  camera.pitch_deg = -40.0f;
  RenderOptions options;
  options.lod.forcedLevel = kLevelImpostor;
  options.shadowReach = {40.0f, 200.0f};  // the trees many texels wide in every map
  options.timePasses = true;
  constexpr int kSize = 320;
  struct Picture {
    Image image;
    std::size_t colourFragments = 0, shadowFragments = 0;  // the trees'
  };
  auto draw = [&](bool crop) {
    ImpostorSettings settings;
    settings.cropSprites = crop;
    SceneRenderer renderer(terrain, 46.0, &library, settings);
    const RenderTarget target = RenderTarget::create(kSize, kSize);
    renderer.render(&forest, camera, options, target);  // bakes the atlases
    const FrameStats trees = renderer.render(&forest, camera, options, target);
    Picture picture{readPixels(kSize, kSize)};
    const FrameStats ground = renderer.render(&none, camera, options, target);
    const auto colour = static_cast<int>(RenderPass::Impostors);
    picture.colourFragments = trees.passFragments[colour];
    for (int pass = 0; pass < kShadowCascades; ++pass)
      picture.shadowFragments += trees.passFragments[pass] - ground.passFragments[pass];
    return picture;
  };
  const Picture square = draw(false), cropped = draw(true);
  EXPECT_LT(meanAbsoluteDifference(square.image, cropped.image), 0.01);
  int speckles = 0;
  for (std::size_t p = 0; p < square.image.rgba.size(); p += 4) {
    int difference = 0;
    for (int c = 0; c < 3; ++c)
      difference += std::abs(int(square.image.rgba[p + c]) - int(cropped.image.rgba[p + c]));
    speckles += difference > 10;
  }
  EXPECT_LE(speckles, 20);
  if (square.colourFragments == 0) GTEST_SKIP() << "the GL counts no fragments";
  // Seen from the side a crown's frame is about as tall as its bounding sphere, so the colour
  // pass gains little; seen from the sun a crown's disc is a small part of it.
  EXPECT_LE(cropped.colourFragments, square.colourFragments);
  EXPECT_LT(cropped.shadowFragments, 0.7 * square.shadowFragments);
}

// A crown narrower or wider than its type's (Forest::place scales its width by 0.7 to 1.4)
// keeps that width as an impostor: at high's switching size the impostor covers the mesh's
// pixels to within 20 %, as the type's own shape does above. Measured: 195 pixels against
// the mesh's 186 (0.7) and 393 against 387 (1.4); shown as the type's frame stretched to the
// larger of the two scales, as before, 283 and 548.
// The atlases a renderer bakes are kept in the cache folder (ImpostorSettings::cacheFolder)
// and the next renderer of the same trees reads them instead of baking: the same picture to
// the byte, without uploading the meshes they are baked from. A damaged file is baked again,
// and a change to what an atlas is made from (here the tile size) misses the cache.
TEST(Impostor, ACachedAtlasDrawsTheBakedPictureWithoutBaking) {
  test::useHeadlessGl();
  const TreeLibrary& library = test::smallLibrary();
  const Terrain terrain = test::flatTerrain(65, 10.0);
  Forest forest = rowOfTrees(library, 6);  // a mature maple's source
  forest.add(library, library.typeIndex(0, 0, 0), worldFromMap(150, 60, 100),
             library.type(library.typeIndex(0, 0, 0)).height_m, 0.0f, 1.0f, 7);  // and another
  Camera camera;
  camera.position = worldFromMap(160, -10, 150);
  camera.pitch_deg = -40.0f;
  RenderOptions options;
  options.lod.forcedLevel = kLevelImpostor;
  constexpr int kSize = 160;
  struct Drawn {
    Image image;
    ForestStats stats;
    ForestGpuMemory memory;
  };
  auto draw = [&](const ImpostorSettings& settings) {
    SceneRenderer renderer(terrain, 46.0, &library, settings);
    const RenderTarget target = RenderTarget::create(kSize, kSize);
    const FrameStats stats = renderer.render(&forest, camera, options, target);
    return Drawn{readPixels(kSize, kSize), stats.forest, renderer.forest()->gpuMemory()};
  };
  ImpostorSettings settings;
  settings.cacheFolder = test::freshDirectory("atlas_cache");
  const Drawn baked = draw(settings);
  EXPECT_EQ(baked.stats.impostorAtlasesBaked, 2u);
  EXPECT_EQ(baked.stats.impostorAtlasesCached, 0u);
  const Drawn cached = draw(settings);
  EXPECT_EQ(cached.stats.impostorAtlasesBaked, 0u);
  EXPECT_EQ(cached.stats.impostorAtlasesCached, 2u);
  EXPECT_TRUE(cached.image.rgba == baked.image.rgba) << "the same picture to the byte";
  EXPECT_EQ(cached.memory.impostorBytes, baked.memory.impostorBytes);
  EXPECT_EQ(cached.memory.meshBytes, 0u) << "no mesh uploaded to bake from";
  EXPECT_GT(baked.memory.meshBytes, 0u);
  // One file damaged: that atlas is baked again, the other read, the picture the same.
  std::filesystem::path file;
  for (const auto& entry : std::filesystem::directory_iterator(settings.cacheFolder))
    file = entry.path();
  test::writeFile(file, test::readFile(file).substr(0, 1000));
  const Drawn repaired = draw(settings);
  EXPECT_EQ(repaired.stats.impostorAtlasesBaked, 1u);
  EXPECT_EQ(repaired.stats.impostorAtlasesCached, 1u);
  EXPECT_TRUE(repaired.image.rgba == baked.image.rgba);
  // Other settings, other atlases.
  ImpostorSettings smaller = settings;
  smaller.tilePixels = 32;
  EXPECT_EQ(draw(smaller).stats.impostorAtlasesBaked, 2u);
  // No folder, no cache.
  EXPECT_EQ(draw(ImpostorSettings{}).stats.impostorAtlasesBaked, 2u);
}

// Sources whose atlases would be made alike share one, baked once: a young beech (the
// library's youngest age class) has no branches yet below a third or half of its height,
// so its crown classes' clear boles prune nothing and their meshes are the same.
TEST(Impostor, SourcesMadeAlikeShareOneAtlas) {
  test::useHeadlessGl();
  LibrarySettings settings = LibrarySettings::shaped(true);
  settings.variants = 1;
  settings.ageClasses = {0.15};
  const TreeLibrary library({test::namedLibrarySpecies("beech")}, settings);
  const ImpostorSettings impostors;
  const int open = library.typeIndex(0, 0, 0, 0), pruned = library.typeIndex(0, 0, 0, 1);
  ASSERT_NE(library.impostorSource(open), library.impostorSource(pruned));
  auto bytesOf = [&](int type) {
    std::string bytes;
    for (const WindPart& part : library.type(type).meshes.lods[impostors.bakeLod].parts) {
      for (const TreeVertex& v : part.vertices) {
        const PackedTreeVertex p = packVertex(v);
        bytes.append(reinterpret_cast<const char*>(&p), sizeof p);
      }
      bytes.append(reinterpret_cast<const char*>(part.indices.data()), part.indices.size() * 4);
    }
    return bytes;
  };
  ASSERT_EQ(bytesOf(open), bytesOf(pruned)) << "the premise: the same mesh";
  FrameUniformBuffer uniforms;
  ForestRenderer renderer(library, impostors, uniforms);
  Forest forest;
  for (const int type : {open, pruned})
    forest.add(library, type, worldFromMap(160, 60, 100), library.type(type).height_m, 0.0f, 1.0f,
               type);
  Camera camera;
  camera.position = worldFromMap(160, 20, 105);
  LodSettings lod;
  lod.forcedLevel = kLevelImpostor;
  std::vector<std::pair<std::size_t, std::size_t>> progress;
  renderer.onAtlasProgress(
      [&](std::size_t done, std::size_t total) { progress.emplace_back(done, total); });
  const ForestStats stats = renderer.prepare(forest, camera, 640, 360, lod, {});
  EXPECT_EQ(stats.impostorAtlasesBaked, 1u);
  using Step = std::pair<std::size_t, std::size_t>;
  EXPECT_EQ(progress, (std::vector<Step>{{1, 2}, {2, 2}})) << "each source given its atlas";
  const std::size_t side = static_cast<std::size_t>(impostors.frames * impostors.tilePixels);
  EXPECT_EQ(renderer.gpuMemory().impostorBytes, 3 * 4 * side * side * 4 / 3) << "one atlas";
}

TEST(Impostor, KeepsItsTreesCrownWidth) {
  test::useHeadlessGl();
  for (float widthRatio : {0.7f, 1.4f}) {
    SCOPED_TRACE(widthRatio);
    const LoneMaple maple(widthRatio);
    SceneRenderer renderer(maple.terrain, 46.0, &maple.library,
                           impostorSettingsFor(RenderQuality::High));
    const float switchPixels = switchPixelsFor(RenderQuality::High)[2];
    PicturesAtLevels pictures(renderer, maple.forest, maple.seenAt(switchPixels),
                              LoneMaple::pictureSize(switchPixels));
    const double mesh = pictures.treePixelsAt(0);
    const double impostor = pictures.treePixelsAt(kLevelImpostor);
    EXPECT_NEAR(impostor / mesh, 1.0, 0.2) << mesh << " vs " << impostor;
  }
}

// A camera `distance` from `target` on its south side, `elevation_deg` above it, looking at
// it.
Camera seenFromTheSouth(glm::vec3 target, float distance, float elevation_deg) {
  Camera camera;
  const float elevation = glm::radians(elevation_deg);
  camera.position =
      target + distance * glm::vec3(0.0f, std::sin(elevation), std::cos(elevation));  // +z
  camera.pitch_deg = -elevation_deg;
  return camera;
}

// The mean luma of the trees' pixels (treePixels) in linear light, 0..255: a speckled mesh
// and a smooth impostor that send as much light to the eye compare equal, where a mean of
// the sRGB bytes would read the speckle darker.
double linearLumaOfTrees(const Image& image, const Image& background) {
  auto linear = [](int byte) {
    const double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t p = 0; p < image.rgba.size(); p += 4) {
    if (!isTreePixel(image, background, p)) continue;
    ++count;
    sum += 0.2126 * linear(image.rgba[p]) + 0.7152 * linear(image.rgba[p + 1]) +
           0.0722 * linear(image.rgba[p + 2]);
  }
  return 255.0 * sum / std::max<double>(count, 1.0);
}

// A crown narrower or wider than its type's is lit more as its mesh is: the impostor turns
// its frames' mean normals by the tree's proportions as the mesh's vertex shader turns its
// normals (toward the horizontal in a slender crown, which then takes less of a high sun).
// A maple at 0.7 and at 1.4 of its type's width, seen from 30 degrees above at high's
// switching size without shadows (linear luma of the tree's pixels, 0..255): the mesh is
// 50.6 and 64.2, the impostor 57.9 and 60.1, so the wider impostor is the brighter, as the
// wider mesh is, and each lies within 9 of its mesh. With the normals not turned, as
// before, the impostors were 59.3 and 58.9: the wider the darker. What is left is which
// leaves a squeezed crown shows (its upward leaves shrink more than its upright ones, where
// a frame shows its type's own mix: docs/rendering.md, "Impostors").
TEST(Impostor, IsLitMoreAsItsMeshAtItsOwnProportions) {
  test::useHeadlessGl();
  std::map<float, double> impostorLuma;
  for (float widthRatio : {0.7f, 1.4f}) {
    SCOPED_TRACE(widthRatio);
    const LoneMaple maple(widthRatio);
    SceneRenderer renderer(maple.terrain, 46.0, &maple.library,
                           impostorSettingsFor(RenderQuality::High));
    const float pixels = switchPixelsFor(RenderQuality::High)[2];
    // As far from the crown's middle as seenAt(pixels) puts it, 30 degrees above it.
    const glm::vec3 middle = worldFromMap(160, 160, 100 + 0.5 * maple.height_m);
    const Camera camera =
        seenFromTheSouth(middle, glm::length(maple.seenAt(pixels).position - middle), 30.0f);
    PicturesAtLevels pictures(renderer, maple.forest, camera, LoneMaple::pictureSize(pixels));
    const double mesh = linearLumaOfTrees(pictures.at(0), pictures.background());
    impostorLuma[widthRatio] =
        linearLumaOfTrees(pictures.at(kLevelImpostor), pictures.background());
    EXPECT_NEAR(impostorLuma[widthRatio], mesh, 9.0);
  }
  EXPECT_GT(impostorLuma[1.4f], impostorLuma[0.7f]);
}

// A far pine's impostor covers about what its needles cover: a species that bears needles
// bakes its frames from LOD0 at every quality (impostorBakeLevel), where LOD1
// gathers the needles into cluster cards. A mature pine seen 40 pixels tall from 25 degrees
// above, drawn with balanced's impostor and as LOD0: the two cover the same number of
// pixels to within a fifth. Measured: 35 and 35 (at 80 px 160 against 191); with the frames
// baked from LOD1, as balanced did before, 26 (118).
TEST(Impostor, OfAPineCoversWhatItsNeedlesCover) {
  test::useHeadlessGl();
  static const TreeLibrary library({test::namedLibrarySpecies("pine")},
                                   LibrarySettings{.variants = 1, .ageClasses = {1.0}});
  const Terrain terrain = test::flatTerrain(33, 10.0);
  const int type = library.typeIndex(0, 0, 0);
  const float height = library.type(type).height_m;
  Forest forest;
  forest.add(library, type, worldFromMap(160, 160, 100), height, library.typeCrownRadius_m(type),
             1.0f, 1);
  const float pixels = 40.0f;
  const int size = 2 * static_cast<int>(pixels);
  const float distance = height * Camera{}.pixelsPerRadian(size) / pixels;
  const Camera camera =
      seenFromTheSouth(worldFromMap(160, 160, 100 + 0.5 * height), distance, 25.0f);
  SceneRenderer renderer(terrain, 46.0, &library, impostorSettingsFor(RenderQuality::Balanced));
  PicturesAtLevels pictures(renderer, forest, camera, size);
  const double mesh = pictures.treePixelsAt(0);
  const double impostor = pictures.treePixelsAt(kLevelImpostor);
  EXPECT_NEAR(impostor / mesh, 1.0, 0.2) << mesh << " vs " << impostor;
}

// Crowns one behind the other let light through independently, as layers of leaves do:
// each sprite draws its own thresholds for the hashed alpha test. Four maples a centimetre
// apart (one crown seen four times) cover more pixels than one where their texels are partly
// covered, as 1 - (1 - a)^4 would have it. Measured at 20 pixels: 109 pixels against 66.
// With one threshold a pixel for every sprite, as before, four covered the pixels of one
// (74 and 74), and a closed canopy of sprites showed the dark ground through its gaps.
TEST(Impostor, CrownsOneBehindTheOtherLetLightThroughIndependently) {
  test::useHeadlessGl();
  LoneMaple maple;
  SceneRenderer renderer(maple.terrain, 46.0, &maple.library,
                         impostorSettingsFor(RenderQuality::High));
  const float pixels = 0.5f * switchPixelsFor(RenderQuality::High)[2];
  PicturesAtLevels pictures(renderer, maple.forest, maple.seenAt(pixels),
                            LoneMaple::pictureSize(pixels));
  const double one = pictures.treePixelsAt(kLevelImpostor);
  for (int i = 1; i < 4; ++i) {
    maple.forest.add(maple.library, maple.forest.type[0],
                     maple.forest.position[0] + glm::vec3(0.0f, 0.0f, 0.01f * i), maple.height_m,
                     0.0f, 1.0f, 1);
    maple.forest.yaw.back() = maple.forest.yaw[0];
  }
  const double four = pictures.treePixelsAt(kLevelImpostor);
  EXPECT_GT(four, 1.1 * one) << one << " vs " << four;
}

// As a tree turns (or the camera moves round it) in steps of a degree, its impostor at the
// balanced switching size changes by less than its mesh does, with frame blending; showing
// the nearest frame alone, it stands still and then jumps where the frames change (every 13
// degrees around the horizon ring). Measured, the largest step's mean difference (of 255):
// mesh 1.37, blended 0.30, nearest frame 2.30.
TEST(Impostor, BlendingFramesTurnsTheTreeWithoutJumps) {
  test::useHeadlessGl();
  LoneMaple maple;
  Forest& forest = maple.forest;
  const float switchPixels = switchPixelsFor(RenderQuality::Balanced)[2];
  const int size = LoneMaple::pictureSize(switchPixels);
  const Camera camera = maple.seenAt(switchPixels);
  RenderOptions options;
  options.shadows = false;
  const RenderTarget target = RenderTarget::create(size, size);
  // The largest change of the picture (mean over its pixels) from one degree to the next.
  auto largestStep = [&](SceneRenderer& renderer, int level) {
    options.lod.forcedLevel = level;
    double largest = 0.0;
    Image previous;
    for (int degree = 0; degree <= 30; ++degree) {
      forest.yaw[0] = glm::radians(static_cast<float>(degree));
      renderer.render(&forest, camera, options, target);
      Image picture = readPixels(size, size);
      if (degree > 0) largest = std::max(largest, meanAbsoluteDifference(picture, previous));
      previous = std::move(picture);
    }
    return largest;
  };
  ImpostorSettings blended = impostorSettingsFor(RenderQuality::Balanced), nearest = blended;
  ASSERT_TRUE(blended.blendFrames);
  nearest.blendFrames = false;
  SceneRenderer blending(maple.terrain, 46.0, &maple.library, blended);
  SceneRenderer jumping(maple.terrain, 46.0, &maple.library, nearest);
  const double mesh = largestStep(blending, 0);
  const double blend = largestStep(blending, kLevelImpostor);
  const double jump = largestStep(jumping, kLevelImpostor);
  EXPECT_LT(blend, mesh);
  EXPECT_GT(jump, 4.0 * blend);
}

// The vertex shader itself, read back with transform feedback: the displaced vertices of
// `mesh` (the tree frame) for one instance under these frame uniforms.
std::vector<glm::vec3> shadedPositions(const WindMesh& mesh, const FrameUniforms& u,
                                       const InstanceAttributes& instance) {
  const RenderTarget target = RenderTarget::create(16, 16);  // draws need a framebuffer
  target.bind();
  std::vector<PackedTreeVertex> vertices;  // as the renderer uploads them
  for (const WindPart& part : mesh.parts)
    for (const TreeVertex& v : part.vertices) vertices.push_back(packVertex(v));
  const Program program({{GL_VERTEX_SHADER, "tree.vert"}}, {"FEEDBACK"}, {"fbLocal"});
  FrameUniformBuffer uniforms;
  uniforms.upload(u);
  const GlName vertexBuffer = makeBuffer(std::span<const PackedTreeVertex>(vertices));
  const GlName instanceBuffer = makeBuffer(&instance, sizeof(instance));
  const GlName output = makeBuffer(nullptr, vertices.size() * sizeof(glm::vec3), GL_MAP_READ_BIT);
  const GlName vao = makeVertexArray();
  setTreeVertexLayout(vao.id());
  setInstanceLayout(vao.id());
  glVertexArrayVertexBuffer(vao.id(), 0, vertexBuffer.id(), 0, sizeof(PackedTreeVertex));
  glVertexArrayVertexBuffer(vao.id(), 1, instanceBuffer.id(), 0, sizeof(InstanceAttributes));

  program.use();
  glBindVertexArray(vao.id());
  glEnable(GL_RASTERIZER_DISCARD);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, output.id());
  glBeginTransformFeedback(GL_POINTS);
  glDrawArraysInstanced(GL_POINTS, 0, static_cast<GLsizei>(vertices.size()), 1);
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  std::vector<glm::vec3> shaded(vertices.size());
  glGetNamedBufferSubData(output.id(), 0, shaded.size() * sizeof(glm::vec3), shaded.data());
  checkGl("transform feedback");
  return shaded;
}

// Against the CPU skeleton's mesh at the same t.
TEST(WindMesh, TheVertexShaderSwaysLikeTheCpuSkeleton) {
  test::useHeadlessGl();
  const Species maple = test::loadNamedSpecies("maple");
  const double age = 0.6, t = 2.4;
  const TreeWind wind{2.0, {0.0, 0.0}};
  const WindLods lods = buildWindLods(maple, 3, age);
  const WindMesh& mesh = lods.lods[0];
  FrameUniforms u;
  u.camera.w = static_cast<float>(t);
  u.wind = glm::vec4(0.0f, 0.0f, 2.0f, 0.0f);
  // Yaw 0, scale 1, phase 0: the tree frame is the world frame.
  const InstanceAttributes instance{glm::vec4(0.0f), glm::vec4(1, 1, 0, 0), glm::vec4(1.0f)};
  const std::vector<glm::vec3> shaded = shadedPositions(mesh, u, instance);

  const test::Agreement a =
      test::agreement(mesh, shaded, test::cpuPositions(maple, age, wind, t, 0));
  EXPECT_GT(a.tipDisplacement, 0.05f);
  EXPECT_LT(a.tipError, 0.08f * a.tipDisplacement + 0.01f)
      << "tip moved " << a.tipDisplacement << " m, shader off by " << a.tipError << " m";
  EXPECT_LT(a.rmsError, 0.1f * a.rmsDisplacement + 0.005f);
}

// A site's lean is given in the world (east, south) and leans a turned tree the same way:
// its crown moves toward the world's east whatever the tree's yaw.
TEST(WindMesh, TheVertexShaderLeansATurnedTreeTowardItsLeanInTheWorld) {
  test::useHeadlessGl();
  const WindLods lods = buildWindLods(test::loadNamedSpecies("beech"), 3, 0.7);
  const WindMesh& mesh = lods.lods[0];
  const float yaw = 2.1f;
  const InstanceAttributes upright{glm::vec4(0, 0, 0, yaw), glm::vec4(1, 1, 0, 0), glm::vec4(1.0f),
                                   glm::vec2(0.0f)};
  InstanceAttributes leaning = upright;
  leaning.lean = glm::vec2(2.0f, 0.0f);
  const std::vector<glm::vec3> rest = shadedPositions(mesh, {}, upright);
  const std::vector<glm::vec3> leant = shadedPositions(mesh, {}, leaning);
  // The foliage's mean move, turned from the tree frame into the world as prepare() does.
  glm::vec3 move(0.0f);
  std::size_t i = 0, leaves = 0;
  for (const WindPart& part : mesh.parts)
    for (std::size_t v = 0; v < part.vertices.size(); ++v, ++i)
      if (part.material != MaterialKind::Bark) move += leant[i] - rest[i], ++leaves;
  move /= static_cast<float>(leaves);
  const float c = std::cos(yaw), s = std::sin(yaw);
  const glm::vec3 world(c * move.x - s * move.z, move.y, s * move.x + c * move.z);
  EXPECT_GT(world.x, 0.3f);
  EXPECT_LT(std::abs(world.z), 0.1f * world.x);
}

}  // namespace
}  // namespace eco
