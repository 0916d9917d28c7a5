// The random variables of RL-systems (Lluch et al., Table 1): continuous Constant, Uniform,
// Exponential and Normal; discrete Constant, Uniform, Binomial and Poisson. Deviates come
// from core/random's counter-based streams, so a derivation is the same on any thread count.
#pragma once

#include <string>
#include <vector>

#include "core/random.hpp"
#include "model/lsystem/expression.hpp"

namespace eco {

enum class Distribution { Constant, Uniform, Exponential, Normal, Binomial, Poisson };

// Largest Poisson mean and binomial trial count: both are sampled by inversion, whose cost
// grows with them, and e^-lambda must not underflow.
inline constexpr double kMaxPoissonMean = 500.0;
inline constexpr double kMaxBinomialTrials = 100000.0;

struct RandomVariable {
  std::string name;
  bool discrete = false;
  Distribution distribution = Distribution::Constant;
  // Constant(a); Uniform(a, b); Exponential(a = rate); Normal(a = mean, b = standard
  // deviation); Binomial(a = trials, b = probability); Poisson(a = mean).
  double a = 0.0;
  double b = 0.0;

  double sample(Rng& rng) const;
  double mean() const;
  double variance() const;
};

// "UNIFORM" -> Distribution::Uniform; nullopt-like false when unknown.
bool distributionFromName(const std::string& upperName, Distribution& out);
const char* distributionName(Distribution distribution);
// How many parameters a distribution takes (1 or 2).
int distributionArity(Distribution distribution);
// Empty when (discrete, distribution, a, b) is valid, else why not.
std::string checkRandomVariable(const RandomVariable& variable);

// The deviates of one module's derivation, drawn on demand from its stream key: the same
// (key, variable, occurrence) always gives the same deviate, whoever asks and when.
class VariableDeviates final : public DeviateSource {
 public:
  VariableDeviates(const std::vector<RandomVariable>& variables, std::uint64_t key)
      : variables_(variables), key_(key) {}
  double deviate(int variable, std::uint32_t occurrence) const override {
    Rng rng(streamKey(key_, static_cast<std::uint64_t>(variable), occurrence));
    return variables_[static_cast<std::size_t>(variable)].sample(rng);
  }

 private:
  const std::vector<RandomVariable>& variables_;
  std::uint64_t key_;
};

}  // namespace eco
