// EcoMod's parameters as data: each global parameter and each local graph of a species with
// its key in the species file, the paper's symbol, its bounds and where it lives in a
// Species. The file reader (species.cpp), the writer (species_writer.hpp) and the tree
// designer (design/) all read these tables, so every bound is written once.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "core/range.hpp"
#include "model/local_params.hpp"
#include "model/species.hpp"

namespace eco {

// The scalar parameters of [strand] that the paper's dialog (its Fig. 1) edits with sliders.
enum class GlobalParameter {
  Strands,
  TrunkLength,
  Kd,
  Phyllotaxis,
  Kc,
  LeafSize,
  LeafDensity,
  WindDirected,
  WindUndirected,
  Flexibility,
};
inline constexpr int kGlobalParameterCount = 10;

struct GlobalParameterInfo {
  GlobalParameter parameter;
  std::string_view key;     // in [strand]
  std::string_view symbol;  // the paper's
  std::string_view meaning;
  Range valid;   // what a species file may hold
  Range slider;  // the paper's slider bounds (Zamuda et al., section II.A)
  bool integer = false;
};
std::span<const GlobalParameterInfo> globalParameters();  // in the enum's order
const GlobalParameterInfo& infoOf(GlobalParameter parameter);
std::optional<GlobalParameter> findGlobalParameter(std::string_view key);

double valueOf(const Species& species, GlobalParameter parameter);
// Stores `value` clamped to the parameter's valid range (rounded for an integer).
void setValue(Species& species, GlobalParameter parameter, double value);

// Which order a local graph runs over.
enum class BranchOrder { Gravelius, Weibull };
// The abscissae the paper's graphs show: g in [0, 15], w in [0, 50] (section III.A).
Range orderAxis(BranchOrder order);

// The twelve auxiliary graphs of eqs. (1)-(6).
enum class LocalGraph {
  KsG,
  KsW,
  AlphaG,
  AlphaW,
  AlphaMG,
  AlphaMW,
  MaxLenG,
  MaxLenW,
  KlG,
  KlW,
  MinLenG,
  MinLenW
};
inline constexpr int kLocalGraphCount = 12;

struct LocalGraphInfo {
  LocalGraph graph;
  std::string_view key;     // in [strand.local]
  std::string_view symbol;  // the paper's
  Range values;             // the ordinate's bounds (section II.B)
  BranchOrder over;
};
std::span<const LocalGraphInfo> localGraphs();  // in the enum's order
const LocalGraphInfo& infoOf(LocalGraph graph);
std::optional<LocalGraph> findLocalGraph(std::string_view key);

Polyline& graphOf(LocalGraphs& graphs, LocalGraph graph);
const Polyline& graphOf(const LocalGraphs& graphs, LocalGraph graph);

// A pair of graphs (g, w) and the combined parameter the model evaluates from them.
struct GraphPair {
  std::string_view name;  // what it controls
  LocalGraph overG, overW;
  Range combined;                        // the bounds of the combined value
  double LocalParams::*value = nullptr;  // the combined value in evaluateLocal()'s result
};
// The six pairs in the order of the paper's Fig. 3 dialogs.
std::span<const GraphPair> graphPairs();
const GraphPair& pairOf(LocalGraph graph);

}  // namespace eco
