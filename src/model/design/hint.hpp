// The paper's visual hint (Zamuda et al., section II.B): "colouring the changing part of the
// tree model so that user always knows what is being changed". A local graph's value at
// order o decides how a segment of that order splits (its strands, its sub-branches'
// angles and lengths: strand_model.cpp), so the hint marks the segments whose order — the
// Gravelius order for a *_g graph, the Weibull order for a *_w graph — lies in the part of
// the graph being edited.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "core/polyline.hpp"
#include "model/mesh/mesh.hpp"
#include "model/skeleton.hpp"
#include "model/species_schema.hpp"

namespace eco {

// A part of a graph's abscissa: orders from lo to hi, with or without the ends.
struct HintInterval {
  LocalGraph graph = LocalGraph::KsG;
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool withEnds = true;

  bool operator==(const HintInterval&) const = default;
  bool contains(double order) const {
    return withEnds ? order >= lo && order <= hi : order > lo && order < hi;
  }
};

// What moving point `index` changes: the open interval between its neighbours; before the
// first and after the last point the graph is constant, so there it reaches to the end.
HintInterval pointInfluence(LocalGraph graph, const Polyline& line, int index);
// One segment of the poly-line, from point `index` to the next, ends included.
HintInterval segmentSpan(LocalGraph graph, const Polyline& line, int index);
// The whole graph: every order.
HintInterval wholeGraph(LocalGraph graph);

// Indices of the skeleton's segments whose order lies in the interval, ascending.
std::vector<std::int32_t> hintedSegments(const TreeSkeleton& skeleton, const HintInterval& hint);

// A bark-material mesh of the hinted segments: a thin sleeve of six sides around each, a
// little wider than the wood (at least kHintMinRadius_m), so that it shows over the bark.
inline constexpr float kHintMinRadius_m = 0.02f;
MeshPart hintSleeves(const TreeSkeleton& skeleton, const std::vector<std::int32_t>& segments);

}  // namespace eco
