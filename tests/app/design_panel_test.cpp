// The designer's panels driven by scripted pointer input through Dear ImGui, headless: the
// same widgets and hit tests the window uses.
#include "app/design_panel.hpp"

#include <memory>

#include <gtest/gtest.h>

#include "model/species.hpp"
#include "render/gl/gl_context.hpp"
#include "render/gl/offscreen_ui.hpp"

namespace eco {
namespace {

class DesignPanel : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { gl_ = std::make_unique<HeadlessGl>(); }

  DesignPanel()
      : session_(loadSpecies(std::string(ECOFOREST_DATA_DIR) + "/species/beech.toml")),
        target_(RenderTarget::create(1600, 900)) {}

  // One frame with the pointer at `at`, the left (or right) button down or not.
  DesignPanelRequests frame(glm::vec2 at, bool left = false, bool right = false) {
    ui_.beginFrame({1600, 900}, at, left, right);
    DesignPanelRequests asked = drawDesignPanels(session_, state_, {}, {}, {1600.0f, 900.0f});
    ui_.drawOnto(target_);
    return asked;
  }
  glm::vec2 point(LocalGraph graph, int index) const {
    return state_.pointPixels[static_cast<int>(graph)][index];
  }
  const Polyline& graph(LocalGraph g) const { return graphOf(session_.species().strand.graphs, g); }

  static inline std::unique_ptr<HeadlessGl> gl_;
  OffscreenUi ui_;
  DesignSession session_;
  DesignPanelState state_;
  RenderTarget target_;
};

TEST_F(DesignPanel, DraggingAPointMovesItAsOneUndoStep) {
  for (int i = 0; i < 3; ++i) frame({-1, -1});        // panels laid out
  const glm::vec2 p = point(LocalGraph::MinLenG, 1);  // (7.5, 0.45) of m^g in [0, 10]
  frame(p);
  frame(p, true);
  for (int dy = 4; dy <= 20; dy += 4) frame(p - glm::vec2(0, dy), true);
  const DesignPanelRequests asked = frame(p - glm::vec2(0, 20), true);
  ASSERT_TRUE(asked.hint.has_value());  // while dragging, the hint is that point's reach
  EXPECT_EQ(asked.hint->graph, LocalGraph::MinLenG);
  EXPECT_EQ(asked.hint->lo, 0.0);
  EXPECT_EQ(asked.hint->hi, 15.0);
  frame(p - glm::vec2(0, 20));
  const ControlPoint moved = graph(LocalGraph::MinLenG).points()[1];
  EXPECT_NEAR(moved.x, 7.5, 1e-9);
  // 20 pixels up a graph 84 pixels tall over [0, 10].
  EXPECT_NEAR(moved.y, 0.45 + 20.0 / 84.0 * 10.0, 0.05);
  EXPECT_TRUE(session_.undo());
  EXPECT_EQ(graph(LocalGraph::MinLenG).points()[1].y, 0.45);
  EXPECT_FALSE(session_.canUndo());
}

TEST_F(DesignPanel, AGrabbedPointKeepsItsOffsetFromThePointer) {
  for (int i = 0; i < 3; ++i) frame({-1, -1});
  const glm::vec2 grab = point(LocalGraph::MinLenG, 1) - glm::vec2(0, 4);  // 4 px above it
  frame(grab);
  frame(grab, true);
  frame(grab, true);  // pressed, not moved: the point stays where it was
  EXPECT_NEAR(graph(LocalGraph::MinLenG).points()[1].y, 0.45, 1e-6);
  frame(grab - glm::vec2(0, 8), true);
  frame(grab - glm::vec2(0, 8));
  EXPECT_NEAR(graph(LocalGraph::MinLenG).points()[1].y, 0.45 + 8.0 / 84.0 * 10.0, 1e-3);
}

TEST_F(DesignPanel, ClickingASegmentAddsAPointThereAndRightClickRemovesIt) {
  for (int i = 0; i < 3; ++i) frame({-1, -1});
  const glm::vec2 a = point(LocalGraph::KsG, 0), b = point(LocalGraph::KsG, 1);
  const glm::vec2 middle = 0.5f * (a + b);
  frame(middle);
  const DesignPanelRequests hover = frame(middle);
  ASSERT_TRUE(hover.hint.has_value());  // hovering a segment hints its span
  EXPECT_TRUE(hover.hint->withEnds);
  frame(middle, true);
  frame(middle);
  ASSERT_EQ(graph(LocalGraph::KsG).points().size(), 3u);
  EXPECT_NEAR(graph(LocalGraph::KsG).points()[1].x, 7.5, 0.1);
  EXPECT_NEAR(graph(LocalGraph::KsG).points()[1].y, graph(LocalGraph::KsG)(7.5), 0.01);
  const glm::vec2 added = point(LocalGraph::KsG, 1);
  frame(added);
  frame(added, false, true);
  frame(added);
  EXPECT_EQ(graph(LocalGraph::KsG).points().size(), 2u);
}

TEST_F(DesignPanel, APinnedHintStaysWhateverThePointerDoes) {
  state_.pinned = GraphFocus{LocalGraph::AlphaW, 0};
  const DesignPanelRequests asked = frame({-1, -1});
  ASSERT_TRUE(asked.hint.has_value());
  EXPECT_EQ(asked.hint->graph, LocalGraph::AlphaW);
  EXPECT_EQ(asked.hint->hi, 50.0);  // the beech's alpha^w: (0, 1), (50, 1)
  EXPECT_FALSE(frame({-1, -1}).save);
}

TEST_F(DesignPanel, ShortcutsUndoRedoAndSave) {
  session_.apply(SetGlobal{GlobalParameter::Kc, 0.9});
  DesignPanelRequests asked;
  applyShortcuts({{'Z', false}}, session_, asked);
  EXPECT_EQ(session_.species().strand.kc, 0.3);
  applyShortcuts({{'Z', true}}, session_, asked);
  EXPECT_EQ(session_.species().strand.kc, 0.9);
  applyShortcuts({{'Z', false}, {'Y', false}, {'S', false}}, session_, asked);
  EXPECT_EQ(session_.species().strand.kc, 0.9);
  EXPECT_TRUE(asked.save);
}

}  // namespace
}  // namespace eco
