#include "model/species_schema.hpp"

#include <array>
#include <cmath>

#include "core/error.hpp"

namespace eco {
namespace {

// The paper's slider for S stops at 5000, yet its own pine has S = 6000: the slider bound
// is no validity limit. 100000 keeps a typo from exhausting memory.
constexpr std::array<GlobalParameterInfo, kGlobalParameterCount> kGlobals{{
    {GlobalParameter::Strands,
     "strands",
     "S",
     "total strands (terminal twigs)",
     {1, 100000},
     {1, 5000},
     true},
    {GlobalParameter::TrunkLength,
     "trunk_length_m",
     "l_0",
     "length of the base trunk, m",
     {0, 10},
     {0, 10}},
    {GlobalParameter::Kd, "kd", "k_d", "thickness: diameter = k_d sqrt(S_0)", {0, 0.05}, {0, 0.05}},
    {GlobalParameter::Phyllotaxis,
     "phyllotaxis_deg",
     "alpha_p",
     "phyllotaxis, degrees",
     {0, 360},
     {0, 360}},
    {GlobalParameter::Kc,
     "kc",
     "k_c",
     "gravicentrism: share of the angle the major branch takes",
     {0, 1},
     {0, 1}},
    {GlobalParameter::LeafSize, "leaf_size_m", "l_l", "blade length, m", {0, 0.3}, {0, 0.3}},
    {GlobalParameter::LeafDensity,
     "leaf_density",
     "rho_l",
     "leaves per terminal twig",
     {0, 30},
     {0, 30}},
    {GlobalParameter::WindDirected,
     "wind_directed_wg",
     "w_g",
     "directed wind (growth toward w)",
     {0, 10},
     {0, 10}},
    {GlobalParameter::WindUndirected,
     "wind_undirected_ws",
     "w_s",
     "undirected wind (sway)",
     {0, 10},
     {0, 10}},
    {GlobalParameter::Flexibility,
     "flexibility_kf",
     "k_f",
     "stiffness: sway scales with 1 - k_f",
     {0, 1},
     {0, 1}},
}};

constexpr Range kUnit2{0, 2};
constexpr std::array<LocalGraphInfo, kLocalGraphCount> kGraphs{{
    {LocalGraph::KsG, "ks_g", "k_s^g", {0.5, 1}, BranchOrder::Gravelius},
    {LocalGraph::KsW, "ks_w", "k_s^w", kUnit2, BranchOrder::Weibull},
    {LocalGraph::AlphaG, "alpha_g_deg", "alpha^g", {0, 180}, BranchOrder::Gravelius},
    {LocalGraph::AlphaW, "alpha_w", "alpha^w", kUnit2, BranchOrder::Weibull},
    {LocalGraph::AlphaMG, "alpha_m_g_deg", "alpha_m^g", {-180, 180}, BranchOrder::Gravelius},
    {LocalGraph::AlphaMW, "alpha_m_w", "alpha_m^w", kUnit2, BranchOrder::Weibull},
    {LocalGraph::MaxLenG, "max_length_g", "M^g", {0, 10}, BranchOrder::Gravelius},
    {LocalGraph::MaxLenW, "max_length_w", "M^w", kUnit2, BranchOrder::Weibull},
    {LocalGraph::KlG, "kl_g", "k_l^g", {0, 10}, BranchOrder::Gravelius},
    {LocalGraph::KlW, "kl_w", "k_l^w", kUnit2, BranchOrder::Weibull},
    {LocalGraph::MinLenG, "min_length_g", "m^g", {0, 10}, BranchOrder::Gravelius},
    {LocalGraph::MinLenW, "min_length_w", "m^w", kUnit2, BranchOrder::Weibull},
}};

// Fig. 3: a) strands, b) branching angles, c) minimal length, d) maximal length, e) length
// scaling, f) gravimorphism. The combined bounds are those of eqs. (1)-(6).
const std::array<GraphPair, 6> kPairs{{
    {"strand distribution k_s", LocalGraph::KsG, LocalGraph::KsW, {0.5, 1}, &LocalParams::ks},
    {"branching angle alpha, deg",
     LocalGraph::AlphaG,
     LocalGraph::AlphaW,
     {0, 180},
     &LocalParams::alpha_deg},
    {"minimum relative length m",
     LocalGraph::MinLenG,
     LocalGraph::MinLenW,
     {0, 20},
     &LocalParams::minLength},
    {"maximum relative length M",
     LocalGraph::MaxLenG,
     LocalGraph::MaxLenW,
     {0, 20},
     &LocalParams::maxLength},
    {"length scaling k_l", LocalGraph::KlG, LocalGraph::KlW, {0, 20}, &LocalParams::kl},
    {"gravimorphism alpha_m, deg",
     LocalGraph::AlphaMG,
     LocalGraph::AlphaMW,
     {-180, 180},
     &LocalParams::alphaM_deg},
}};

template <typename Info, typename Key>
std::optional<Key> findByKey(std::span<const Info> table, std::string_view key) {
  for (const Info& info : table)
    if (info.key == key) return static_cast<Key>(&info - table.data());
  return std::nullopt;
}

}  // namespace

std::span<const GlobalParameterInfo> globalParameters() {
  return kGlobals;
}

const GlobalParameterInfo& infoOf(GlobalParameter parameter) {
  return kGlobals[static_cast<std::size_t>(parameter)];
}

std::optional<GlobalParameter> findGlobalParameter(std::string_view key) {
  return findByKey<GlobalParameterInfo, GlobalParameter>(kGlobals, key);
}

double valueOf(const Species& species, GlobalParameter parameter) {
  const StrandParams& p = species.strand;
  const WindParams& w = species.wind;
  switch (parameter) {
    case GlobalParameter::Strands:
      return p.strands;
    case GlobalParameter::TrunkLength:
      return p.trunkLength_m;
    case GlobalParameter::Kd:
      return p.kd;
    case GlobalParameter::Phyllotaxis:
      return p.phyllotaxis_deg;
    case GlobalParameter::Kc:
      return p.kc;
    case GlobalParameter::LeafSize:
      return p.leafSize_m;
    case GlobalParameter::LeafDensity:
      return p.leafDensity;
    case GlobalParameter::WindDirected:
      return w.directed_wg;
    case GlobalParameter::WindUndirected:
      return w.undirected_ws;
    case GlobalParameter::Flexibility:
      return w.flexibility;
  }
  ECO_ASSERT(false, "parameter " << static_cast<int>(parameter));
  return 0.0;
}

void setValue(Species& species, GlobalParameter parameter, double value) {
  const GlobalParameterInfo& info = infoOf(parameter);
  value = info.valid.clamp(std::isfinite(value) ? value : info.valid.min);
  if (info.integer) value = std::round(value);
  StrandParams& p = species.strand;
  WindParams& w = species.wind;
  switch (parameter) {
    case GlobalParameter::Strands:
      p.strands = static_cast<int>(value);
      return;
    case GlobalParameter::TrunkLength:
      p.trunkLength_m = value;
      return;
    case GlobalParameter::Kd:
      p.kd = value;
      return;
    case GlobalParameter::Phyllotaxis:
      p.phyllotaxis_deg = value;
      return;
    case GlobalParameter::Kc:
      p.kc = value;
      return;
    case GlobalParameter::LeafSize:
      p.leafSize_m = value;
      return;
    case GlobalParameter::LeafDensity:
      p.leafDensity = value;
      return;
    case GlobalParameter::WindDirected:
      w.directed_wg = value;
      return;
    case GlobalParameter::WindUndirected:
      w.undirected_ws = value;
      return;
    case GlobalParameter::Flexibility:
      w.flexibility = value;
      return;
  }
}

Range orderAxis(BranchOrder order) {
  return order == BranchOrder::Gravelius ? Range{0, 15} : Range{0, 50};
}

std::span<const LocalGraphInfo> localGraphs() {
  return kGraphs;
}

const LocalGraphInfo& infoOf(LocalGraph graph) {
  return kGraphs[static_cast<std::size_t>(graph)];
}

std::optional<LocalGraph> findLocalGraph(std::string_view key) {
  return findByKey<LocalGraphInfo, LocalGraph>(kGraphs, key);
}

Polyline& graphOf(LocalGraphs& graphs, LocalGraph graph) {
  Polyline* all[] = {&graphs.ksG,     &graphs.ksW,     &graphs.alphaG,  &graphs.alphaW,
                     &graphs.alphaMG, &graphs.alphaMW, &graphs.maxLenG, &graphs.maxLenW,
                     &graphs.klG,     &graphs.klW,     &graphs.minLenG, &graphs.minLenW};
  return *all[static_cast<std::size_t>(graph)];
}

const Polyline& graphOf(const LocalGraphs& graphs, LocalGraph graph) {
  return graphOf(const_cast<LocalGraphs&>(graphs), graph);
}

std::span<const GraphPair> graphPairs() {
  return kPairs;
}

const GraphPair& pairOf(LocalGraph graph) {
  for (const GraphPair& pair : kPairs)
    if (pair.overG == graph || pair.overW == graph) return pair;
  ECO_ASSERT(false, "graph " << static_cast<int>(graph));
  return kPairs[0];
}

}  // namespace eco
