#include "model/lsystem/lsystem.hpp"

#include <gtest/gtest.h>

namespace eco {
namespace {

TEST(LSystemString, PrintsModulesConcatenatedWithShortestRoundTripParameters) {
  ModuleString s;
  s.add('A', {1.5, 2.0});
  s.add('[');
  s.add('+', {0.1});
  s.add('F', {1.0 / 3.0});
  s.add(']');
  s.add(kQueryPosition, {0, -2, 1e-7});
  EXPECT_EQ(toString(s), "A(1.5,2)[+(0.1)F(0.3333333333333333)]?P(0,-2,1e-07)");
}

TEST(LSystemString, ControlModulesPrintTheirBodies) {
  ModuleString items;
  items.add('A');
  items.add('B', {2});
  ModuleString s;
  s.add(kSwitch, {1});
  s.modules.back().body = 0;
  s.bodies.push_back(items);
  s.add('%');
  EXPECT_EQ(toString(s), "@Switch(1){AB(2)}%");
  ModuleString copy;
  copy.append(s, 0);
  EXPECT_EQ(toString(copy), "@Switch(1){AB(2)}");
}

TEST(LSystemString, SymbolNamesAndKinds) {
  EXPECT_EQ(symbolName('F'), "F");
  EXPECT_EQ(symbolName(kQueryHeading), "?H");
  EXPECT_EQ(symbolName(kRepetition), "@Repetition");
  EXPECT_EQ(symbolName(kPrune), "%");
  EXPECT_TRUE(isQuery(kQueryLeft));
  EXPECT_FALSE(isQuery('P'));
  EXPECT_TRUE(isControl(kPendulum));
  EXPECT_FALSE(isControl(kPrune));
}

TEST(LSystemString, BranchEndSkipsSubBranchesToTheClosingBracket) {
  ModuleString s;
  for (char c : std::string("F[A[B]C]DE")) s.add(static_cast<Symbol>(c));
  EXPECT_EQ(branchEnd(s, 2), 7u);   // from A: over [B] to the ] after C
  EXPECT_EQ(branchEnd(s, 4), 5u);   // from B: its own ]
  EXPECT_EQ(branchEnd(s, 8), 10u);  // the main axis ends with the string
  EXPECT_EQ(branchEnd(s, 0), 10u);
}

TEST(LSystemString, PruneVolumesContainTheirInsideOnly) {
  PruneVolume ellipsoid{PruneShape::Ellipsoid, {0, 5, 0}, {2, 5, 1}};
  EXPECT_TRUE(ellipsoid.contains({0, 0, 0}));
  EXPECT_TRUE(ellipsoid.contains({2, 5, 0}));
  EXPECT_FALSE(ellipsoid.contains({1.5, 5, 0.8}));
  EXPECT_FALSE(ellipsoid.contains({0, 10.1, 0}));
  PruneVolume box{PruneShape::Box, {-1, 0, -1}, {1, 3, 1}};
  EXPECT_TRUE(box.contains({1, 3, -1}));
  EXPECT_FALSE(box.contains({0, 3.01, 0}));
  EXPECT_TRUE(PruneVolume{}.contains({1e9, 0, 0}));
}

}  // namespace
}  // namespace eco
