#include "model/local_params.hpp"

#include <algorithm>

namespace eco {

LocalParams evaluateLocal(const LocalGraphs& graphs, double g, double w) {
  LocalParams p;
  p.ks = std::clamp(graphs.ksG(g) * graphs.ksW(w), 0.5, 1.0);
  p.alpha_deg = std::min(graphs.alphaG(g) * graphs.alphaW(w), 180.0);
  p.alphaM_deg = std::clamp(graphs.alphaMG(g) * graphs.alphaMW(w), -180.0, 180.0);
  p.maxLength = graphs.maxLenG(g) * graphs.maxLenW(w);
  p.kl = graphs.klG(g) * graphs.klW(w);
  p.minLength = graphs.minLenG(g) * graphs.minLenW(w);
  return p;
}

}  // namespace eco
