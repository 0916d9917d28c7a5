#include "model/design/design_session.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_support.hpp"

namespace eco {
namespace {

std::vector<ControlPoint> points(const DesignSession& session, LocalGraph graph) {
  const Polyline& line = graphOf(session.species().strand.graphs, graph);
  return {line.points().begin(), line.points().end()};
}

}  // namespace

TEST(DesignSession, SetGlobalChangesTheParameterAndClampsToThePapersBounds) {
  DesignSession session(test::loadNamed("beech"));
  session.apply(SetGlobal{GlobalParameter::Kc, 0.55});
  EXPECT_EQ(session.species().strand.kc, 0.55);
  session.apply(SetGlobal{GlobalParameter::LeafSize, 0.9});
  EXPECT_EQ(session.species().strand.leafSize_m, 0.3);
  session.apply(SetGlobal{GlobalParameter::WindDirected, -2.0});
  EXPECT_EQ(session.species().wind.directed_wg, 0.0);
  session.apply(SetLeafDistribution{LeafDistribution::Bunched});
  EXPECT_EQ(session.species().strand.leafDistribution, LeafDistribution::Bunched);
  session.apply(SetWindDirection{{1.0, 1.0, 0.0}});
  EXPECT_EQ(session.species().wind.direction, glm::dvec3(1.0, 1.0, 0.0));
  EXPECT_THROW(session.apply(SetWindDirection{{0.0, 0.0, 0.0}}), EditRefused);
}

TEST(DesignSession, SetNameTakesOnlyAPlainName) {
  DesignSession session(test::loadNamed("beech"));
  session.apply(SetName{"broad_beech"});
  EXPECT_EQ(session.species().name, "broad_beech");
  EXPECT_THROW(session.apply(SetName{"broad beech"}), EditRefused);
  EXPECT_THROW(session.apply(SetName{""}), EditRefused);
  EXPECT_EQ(session.species().name, "broad_beech");
}

TEST(DesignSession, MovePointKeepsItBetweenItsNeighboursAndInsideTheGraph) {
  DesignSession session(test::loadNamed("beech"));  // m^g = (0, 1), (7.5, 0.45), (15, 1)
  session.apply(MovePoint{LocalGraph::MinLenG, 1, 9.25, 0.8});
  EXPECT_EQ(points(session, LocalGraph::MinLenG)[1].x, 9.25);  // not snapped to an order
  EXPECT_EQ(points(session, LocalGraph::MinLenG)[1].y, 0.8);
  session.apply(MovePoint{LocalGraph::MinLenG, 1, 40.0, 25.0});
  EXPECT_EQ(points(session, LocalGraph::MinLenG)[1].x, 15.0);  // the next point's x
  EXPECT_EQ(points(session, LocalGraph::MinLenG)[1].y, 10.0);  // m^g in [0, 10]
  session.apply(MovePoint{LocalGraph::MinLenG, 0, -3.0, -1.0});
  EXPECT_EQ(points(session, LocalGraph::MinLenG)[0].x, 0.0);  // the axis starts at 0
  EXPECT_EQ(points(session, LocalGraph::MinLenG)[0].y, 0.0);
  session.apply(MovePoint{LocalGraph::KsW, 1, 80.0, 1.5});  // w runs to 50
  EXPECT_EQ(points(session, LocalGraph::KsW)[1].x, 50.0);
  EXPECT_EQ(points(session, LocalGraph::KsW)[1].y, 1.5);
  EXPECT_THROW(session.apply(MovePoint{LocalGraph::KsW, 2, 1.0, 1.0}), EditRefused);
}

TEST(DesignSession, AddPointGoesOnTheLineOrWhereAsked) {
  DesignSession session(test::loadNamed("beech"));  // k_s^g = (0, 0.75), (15, 0.9)
  const Species before = session.species();
  session.apply(AddPoint{LocalGraph::KsG, 5.0, std::nullopt});
  ASSERT_EQ(points(session, LocalGraph::KsG).size(), 3u);
  EXPECT_EQ(points(session, LocalGraph::KsG)[1].x, 5.0);
  EXPECT_DOUBLE_EQ(points(session, LocalGraph::KsG)[1].y, 0.8);  // on the line
  for (double g = 0; g <= 15; g += 0.5)
    EXPECT_NEAR(session.species().strand.graphs.ksG(g), before.strand.graphs.ksG(g), 1e-15);
  session.apply(AddPoint{LocalGraph::KsG, 12.0, 0.2});  // clamped to k_s^g >= 1/2
  ASSERT_EQ(points(session, LocalGraph::KsG).size(), 4u);
  EXPECT_EQ(points(session, LocalGraph::KsG)[2].x, 12.0);
  EXPECT_EQ(points(session, LocalGraph::KsG)[2].y, 0.5);
}

TEST(DesignSession, RemovePointKeepsTheLastOne) {
  DesignSession session(test::loadNamed("beech"));
  session.apply(RemovePoint{LocalGraph::MinLenG, 1});
  ASSERT_EQ(points(session, LocalGraph::MinLenG).size(), 2u);
  EXPECT_EQ(points(session, LocalGraph::MinLenG)[1].x, 15.0);
  session.apply(RemovePoint{LocalGraph::MinLenG, 0});
  EXPECT_THROW(session.apply(RemovePoint{LocalGraph::MinLenG, 0}), EditRefused);
  EXPECT_EQ(points(session, LocalGraph::MinLenG).size(), 1u);
}

TEST(DesignSession, UndoAndRedoStepThroughTheEdits) {
  const Species beech = test::loadNamed("beech");
  DesignSession session(beech);
  EXPECT_FALSE(session.canUndo());
  session.apply(SetGlobal{GlobalParameter::Kc, 0.6});
  session.apply(SetGlobal{GlobalParameter::Kd, 0.02});
  EXPECT_TRUE(session.undo());
  EXPECT_EQ(session.species().strand.kd, beech.strand.kd);
  EXPECT_EQ(session.species().strand.kc, 0.6);
  EXPECT_TRUE(session.undo());
  EXPECT_EQ(session.species().strand.kc, beech.strand.kc);
  EXPECT_FALSE(session.undo());
  EXPECT_TRUE(session.redo());
  EXPECT_EQ(session.species().strand.kc, 0.6);
  // A new edit drops what could be redone.
  session.apply(SetGlobal{GlobalParameter::Strands, 500});
  EXPECT_FALSE(session.canRedo());
}

TEST(DesignSession, TheMovesOfOneDragAreOneUndoStep) {
  const Species beech = test::loadNamed("beech");
  DesignSession session(beech);
  for (double y : {0.5, 0.6, 0.7, 0.8}) session.apply(MovePoint{LocalGraph::MinLenG, 1, 7.5, y}, 1);
  for (double y : {0.9, 0.4, 0.3}) session.apply(MovePoint{LocalGraph::MinLenG, 1, 8.0, y}, 2);
  EXPECT_TRUE(session.undo());
  EXPECT_EQ(points(session, LocalGraph::MinLenG)[1].y, 0.8);  // the end of drag 1
  EXPECT_TRUE(session.undo());
  EXPECT_EQ(points(session, LocalGraph::MinLenG)[1].y, 0.45);
  EXPECT_FALSE(session.canUndo());
}

TEST(DesignSession, RefusedEditsChangeNothing) {
  DesignSession session(test::loadNamed("beech"));
  const std::uint64_t version = session.version();
  EXPECT_THROW(session.apply(RemovePoint{LocalGraph::AlphaG, 9}), EditRefused);
  EXPECT_EQ(session.version(), version);
  EXPECT_FALSE(session.canUndo());
}

TEST(DesignSession, RefusesAnLSystemSpecies) {
  EXPECT_THROW(DesignSession(test::loadNamed("birch")), InputError);
}

}  // namespace eco
