// The local (branch-order dependent) parameters of EcoMod, eqs. (1)-(6) of Zamuda et al.
// The paper's prose swaps the equation numbers of m^{g,w} and alpha_m^{g,w}; here each
// equation is applied by meaning: alpha_m is clamped to [-180, 180] degrees, m, M and k_l
// are plain products.
#pragma once

#include "model/species.hpp"

namespace eco {

struct LocalParams {
  double ks = 0.5;          // k_s^{g,w} in [1/2, 1], eq. (1)
  double alpha_deg = 0.0;   // alpha^{g,w} in [0, 180], eq. (2)
  double alphaM_deg = 0.0;  // alpha_m^{g,w} in [-180, 180], eq. (3)
  double maxLength = 1.0;   // M^{g,w} = M^g M^w, eq. (4)
  double kl = 1.0;          // k_l^{g,w} = k_l^g k_l^w, eq. (5)
  double minLength = 0.0;   // m^{g,w} = m^g m^w, eq. (6)
};

LocalParams evaluateLocal(const LocalGraphs& graphs, double g, double w);

}  // namespace eco
