#include "render/gl/design_view.hpp"

#include <gtest/gtest.h>

#include "gl_support.hpp"
#include "render_support.hpp"

namespace eco {
namespace {

// Pixels close to the hint's orange (in sRGB, lit anywhere from shade to sun).
int orangePixels(const Image& image) {
  int n = 0;
  for (std::size_t p = 0; p < image.rgba.size(); p += 4) {
    const int r = image.rgba[p], g = image.rgba[p + 1], b = image.rgba[p + 2];
    n += r > 90 && r > 2 * g && g > 2 * b;
  }
  return n;
}

Image draw(DesignView& view, const PreviewSettings& settings, bool row = true) {
  const RenderTarget target = RenderTarget::create(320, 240);
  view.render(view.framingCamera(), previewRenderOptions(settings, 0.0, 0.0), row, target);
  return readPixels(target);
}

}  // namespace

TEST(DesignView, ShowsTheTreeAndColoursTheHintedBranches) {
  test::useHeadlessGl();
  const Species beech = test::loadNamedSpecies("beech");
  DesignView view(beech, {}, buildCompletePreview(beech, {}, {}));
  const Image plain = draw(view, {});
  EXPECT_EQ(orangePixels(plain), 0);
  // The tree stands in the middle of the picture: its centre is not sky.
  const glm::vec4 centre = plain.get(160, 120);
  EXPECT_LT(centre.b, centre.g + 0.05f) << centre.r << " " << centre.g << " " << centre.b;

  PreviewSettings hinted;
  hinted.hint = HintInterval{LocalGraph::KsW, -1.0, 1e9, true};  // every segment
  view.show(buildPreview(beech, hinted));
  const Image withHint = draw(view, hinted);
  EXPECT_GT(orangePixels(withHint), 200);
  // The same scene shown again draws the same picture.
  view.show(buildPreview(beech, {}));
  EXPECT_EQ(draw(view, {}).rgba, plain.rgba);
}

TEST(DesignView, ANewerSceneReplacesTheTreeAndTheRowCanBeHidden) {
  test::useHeadlessGl();
  const Species beech = test::loadNamedSpecies("beech");
  DesignView view(beech, {}, buildCompletePreview(beech, {}, {}));
  const Image before = draw(view, {}, false);
  Species wider = beech;
  wider.strand.graphs.alphaG = Polyline::constant(80.0);
  view.show(buildPreview(wider, {}));  // the edited tree only, the row kept
  EXPECT_NE(draw(view, {}, false).rgba, before.rgba);
  EXPECT_EQ(view.shown().settings, PreviewSettings{});
}

TEST(DesignView, ShowsEachLevelIncludingTheImpostor) {
  test::useHeadlessGl();
  const Species beech = test::loadNamedSpecies("beech");
  DesignView view(beech, {}, buildCompletePreview(beech, {}, {}));
  std::vector<std::vector<std::uint8_t>> pictures;
  for (int level = 0; level < kLevelCount; ++level) {
    PreviewSettings settings;
    settings.level = level;
    view.show(buildCompletePreview(beech, {}, settings));
    const Image image = draw(view, settings, false);
    const glm::vec4 centre = image.get(160, 120);
    EXPECT_LT(centre.b, centre.g + 0.05f) << "level " << level;  // a tree, not sky
    pictures.push_back(image.rgba);
  }
  for (int level = 1; level < kLevelCount; ++level) EXPECT_NE(pictures[level], pictures[0]);
}

}  // namespace eco
