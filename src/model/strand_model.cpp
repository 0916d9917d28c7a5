#include "model/strand_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/error.hpp"
#include "core/random.hpp"
#include "core/rotation.hpp"
#include "model/leaves.hpp"
#include "model/local_params.hpp"
#include "model/wind.hpp"

namespace eco {
namespace {

// One call of Algorithm 1's branchsegment(), before frames are known.
struct Node {
  std::int32_t parent = -1;
  int g = 0, w = 0;
  int strands = 1;               // S_0
  int majorStrands = 0;          // S_1 of the split at this node's tip (0 for a terminal)
  std::int32_t majorChild = -1;  // node index of the major sub-branch
  double fullLength = 0.0;       // l_0 at maturity, metres
  double branchAngle = 0.0;      // +alpha_1 (major) or -alpha_2 (minor), degrees, from the parent
  bool major = false;
  // Used for this node's own split:
  double alphaM_deg = 0.0;             // alpha_m^{g,w}
  double phyllotaxis_deg = 0.0;        // alpha_p with individual jitter
  float phaseX = 0.0f, phaseZ = 0.0f;  // R_x, R_z
};

struct PendingCall {
  std::int32_t parent;
  int g, w, strands;
  double relativeLength;  // L_0
  double activeLength;    // l_0 before individual variation
  double branchAngle;
  bool major;
};

// Pass 1: the topology and mature lengths of Algorithm 1, in depth-first pre-order (each
// node before the minor, then the major sub-branch, as the recursion visits them).
std::vector<Node> splitStrands(const Species& species, std::uint64_t seed) {
  const StrandParams& p = species.strand;
  const Variation& v = species.variation;
  std::vector<Node> nodes;
  nodes.reserve(2 * static_cast<std::size_t>(p.strands));
  std::vector<PendingCall> stack;
  stack.push_back({-1, 0, 0, p.strands, 1.0, p.trunkLength_m, 0.0, false});
  while (!stack.empty()) {
    PendingCall call = stack.back();
    stack.pop_back();
    const auto index = static_cast<std::int32_t>(nodes.size());
    Rng rng(streamKey(seed, static_cast<std::uint64_t>(index), purpose("strand-node")));

    Node node;
    node.parent = call.parent;
    node.g = call.g;
    node.w = call.w;
    node.strands = call.strands;
    node.major = call.major;
    node.branchAngle = call.branchAngle;
    node.fullLength = call.activeLength * (1.0 + v.length * rng.uniform(-1.0, 1.0));
    if (call.parent >= 0 && call.major) nodes[call.parent].majorChild = index;
    if (node.strands > 1) {
      LocalParams local = evaluateLocal(p.graphs, node.g, node.w);
      const double s0 = node.strands;
      // S1 = ceil(1 + k_s (S0 - 2)); the epsilon keeps 4.0000000001 from rounding up to 5,
      // and the clamp keeps both sub-branches non-empty.
      int s1 = static_cast<int>(std::ceil(1.0 + local.ks * (s0 - 2.0) - 1e-9));
      s1 = std::clamp(s1, 1, node.strands - 1);
      int s2 = node.strands - s1;
      double r1 = std::max(std::min(std::sqrt(s1 / s0), local.maxLength), local.minLength);
      double r2 = std::max(std::min(std::sqrt(s2 / s0), local.maxLength), local.minLength);
      double L1 = r1 * call.relativeLength;
      double L2 = r2 * call.relativeLength;
      double alpha = local.alpha_deg * (1.0 + v.branchAngle * rng.uniform(-1.0, 1.0));
      double alpha1 = species.strand.kc * std::sqrt(s2 / s0) * alpha;
      double alpha2 = alpha - alpha1;
      node.majorStrands = s1;
      node.alphaM_deg = local.alphaM_deg;
      node.phyllotaxis_deg = p.phyllotaxis_deg + v.phyllotaxis_deg * rng.uniform(-1.0, 1.0);
      node.phaseX = static_cast<float>(rng.uniform(0.0, 2.0 * std::numbers::pi));
      node.phaseZ = static_cast<float>(rng.uniform(0.0, 2.0 * std::numbers::pi));
      // The major and minor sub-branches turn to opposite sides so that the angle between
      // them is alpha_1 + alpha_2 = alpha^{g,w}. Pushed major first: the minor pops first.
      stack.push_back({index, node.g, node.w + 1, s1, L1, local.kl * L1, +alpha1, true});
      stack.push_back({index, node.g + 1, node.w + 1, s2, L2, local.kl * L2, -alpha2, false});
    }
    nodes.push_back(node);
  }
  return nodes;
}

}  // namespace

TreeSkeleton buildStrandTree(const Species& species, const TreeBuildOptions& options) {
  TreeSkeleton skeleton;
  buildStrandTreeInto(species, options, skeleton);
  return skeleton;
}

void buildStrandTreeInto(const Species& species, const TreeBuildOptions& options,
                         TreeSkeleton& skeleton) {
  const StrandParams& p = species.strand;
  ECO_ASSERT(p.strands >= 1, "strands=" << p.strands);
  const std::vector<Node> nodes = splitStrands(species, options.seed);

  // Growth (docs/model.md): development runs through the Weibull orders one after another
  // -- segments of order w lengthen from zero while development passes from w/W to
  // (w+1)/W -- and the whole tree scales with the square root of development. Children
  // emerge at zero length when their parent is complete; nothing jumps.
  int deepest = 0;
  for (const Node& n : nodes) deepest = std::max(deepest, n.w);
  const double orders = deepest + 1.0;
  const double age = std::clamp(options.age, 0.0, 1.0);
  const double development = kSeedlingFraction + (1.0 - kSeedlingFraction) * age;
  const bool mature = age >= 1.0;
  const double scale = mature ? 1.0 : std::sqrt(development);
  std::vector<double> progress(nodes.size());  // 0 unborn .. 1 full length, of each node
  for (std::size_t i = 0; i < nodes.size(); ++i)
    progress[i] = mature ? 1.0 : std::clamp(development * orders - nodes[i].w, 0.0, 1.0);

  skeleton.segments.clear();
  skeleton.leaves.clear();
  skeleton.segments.reserve(nodes.size());
  std::vector<std::int32_t> segmentOf(nodes.size(), -1);

  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Node& node = nodes[i];
    if (node.parent >= 0 && progress[i] <= 0.0) continue;
    BranchSegment seg;
    seg.length_m = static_cast<float>(node.fullLength * progress[i] * scale);
    seg.gravelius = static_cast<std::int16_t>(node.g);
    seg.weibull = static_cast<std::int16_t>(node.w);
    seg.strands = node.strands;
    seg.continuesParent = node.major;
    seg.windPhaseX = node.phaseX;
    seg.windPhaseZ = node.phaseZ;
    // Thickness from Mandelbrot: d = k_d sqrt(S_0); the whole tree thickens as it grows.
    const double girth = 0.5 * p.kd * development;
    seg.startRadius_m = static_cast<float>(girth * std::sqrt(node.strands));
    seg.endRadius_m = static_cast<float>(
        node.majorStrands > 0 ? girth * std::sqrt(node.majorStrands) : 0.5 * seg.startRadius_m);
    if (node.parent >= 0) {
      // The joint of Algorithm 1: the parent's split turns the sub-branch by its phyllotaxis
      // and branching angle, and gravimorphism bends it by alpha_m: alpha_m > 0 toward the
      // downward vertical (sagging), alpha_m < 0 against gravity (docs/model.md says why).
      // The wind poses the frames from these below.
      const Node& parentNode = nodes[node.parent];
      seg.parent = segmentOf[node.parent];
      seg.twist = rotationY(parentNode.phyllotaxis_deg);
      seg.bend_deg = node.branchAngle;
      seg.gravimorphism_deg = parentNode.alphaM_deg;
    }
    segmentOf[i] = static_cast<std::int32_t>(skeleton.segments.size());
    skeleton.segments.push_back(seg);
  }
  poseSkeleton(skeleton, windOf(species, options));

  if (options.leaves && p.leafDensity > 0.0 && p.leafSize_m > 0.0) {
    skeleton.leaves.reserve(static_cast<std::size_t>(p.strands * std::ceil(p.leafDensity)));
    // A fractional density gives floor or ceil leaves per twig: at most two patterns.
    const int fewest = static_cast<int>(std::floor(p.leafDensity));
    const LeafPattern patterns[2] = {makeLeafPattern(p.leafDistribution, fewest),
                                     makeLeafPattern(p.leafDistribution, fewest + 1)};
    auto grownFraction = [&](std::int32_t n) { return n < 0 ? 0.0 : progress[n]; };
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (segmentOf[i] < 0) continue;
      const BranchSegment& twig = skeleton.segments[segmentOf[i]];
      // Leaves unfold as their twig lengthens. While a tree grows, the current tip of
      // every shoot carries leaves too: they shrink away as the shoot's major sub-branch
      // grows and takes over, so a sapling is leafy and the mature tree keeps only the
      // terminal strands' leaves, without any leaf popping in or out.
      double unfolded = grownFraction(static_cast<std::int32_t>(i));
      if (nodes[i].strands > 1) unfolded *= 1.0 - grownFraction(nodes[i].majorChild);
      if (unfolded <= 0.0) continue;
      Rng rng(streamKey(options.seed, i, purpose("leaves")));
      const LeafPattern& pattern = patterns[rng.stochasticRound(p.leafDensity) - fewest];
      auto size = static_cast<float>(p.leafSize_m * unfolded);
      if (size < 1e-4f) continue;
      placeLeaves(twig, segmentOf[i], pattern, size, rng, skeleton.leaves);
    }
  }
}

}  // namespace eco
