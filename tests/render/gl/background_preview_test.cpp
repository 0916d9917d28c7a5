#include "render/gl/background_preview.hpp"

#include <thread>

#include <gtest/gtest.h>

#include "gl_support.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

RenderedPreview waitForPicture(BackgroundPreview& preview) {
  for (int i = 0; i < 1000; ++i) {
    if (std::optional<RenderedPreview> picture = preview.take()) return std::move(*picture);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ADD_FAILURE() << "no picture in 10 s";
  return {};
}

}  // namespace

TEST(BackgroundPreview, DrawsOnItsOwnThreadWhatTheViewDrawsHere) {
  test::useHeadlessGl();
  const Species beech = test::loadNamedSpecies("beech");
  BackgroundPreview preview(beech, {}, buildCompletePreview(beech, {}, {}));
  const OrbitCamera camera = preview.framingCamera();
  preview.request({camera, true, 0.0, 0.0, {200, 150}});
  const RenderedPreview picture = waitForPicture(preview);
  ASSERT_EQ(picture.image.width, 200);
  EXPECT_EQ(picture.stats.segments, 1999u);

  DesignView view(beech, {}, buildCompletePreview(beech, {}, {}));
  const RenderTarget target = RenderTarget::create(200, 150);
  view.render(camera, previewRenderOptions({}, 0.0, 0.0), true, target);
  EXPECT_EQ(readPixels(target).rgba, picture.image.rgba);
}

TEST(BackgroundPreview, ShowsEveryHandedSceneInOrderAndTheNewestFrame) {
  test::useHeadlessGl();
  const Species beech = test::loadNamedSpecies("beech");
  BackgroundPreview preview(beech, {}, buildCompletePreview(beech, {}, {}));
  OrbitCamera camera = preview.framingCamera();
  PreviewSettings halfGrown;
  halfGrown.age = 0.5;
  PreviewScene young = buildPreview(beech, halfGrown);
  young.version = 7;
  preview.request({camera, true, 0.0, 0.0, {64, 48}}, std::move(young));
  camera.yaw_deg = 90.0f;
  preview.request({camera, false, 0.0, 0.0, {80, 60}});
  RenderedPreview last = waitForPicture(preview);
  while (last.image.width != 80) last = waitForPicture(preview);
  EXPECT_EQ(last.settings.age, 0.5);
  EXPECT_LT(last.stats.height_m, 20.0);
}

}  // namespace eco
