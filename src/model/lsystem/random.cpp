#include "model/lsystem/random.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace eco {

double RandomVariable::sample(Rng& rng) const {
  switch (distribution) {
    case Distribution::Constant:
      return a;
    case Distribution::Uniform:
      if (discrete) {  // integers a..b inclusive
        const double count = b - a + 1.0;
        return a + std::min(std::floor(rng.uniform() * count), count - 1.0);
      }
      return rng.uniform(a, b);
    case Distribution::Exponential:
      return -std::log1p(-rng.uniform()) / a;
    case Distribution::Normal:
      return a + b * rng.normal();
    case Distribution::Binomial: {
      // Inversion: walk the cumulative distribution from k = 0.
      const double n = a, p = b;
      if (p <= 0.0) return 0.0;
      if (p >= 1.0) return n;
      const double u = rng.uniform();
      double probability = std::pow(1.0 - p, n), cumulative = probability;
      const double ratio = p / (1.0 - p);
      double k = 0.0;
      while (u >= cumulative && k < n) {
        probability *= ratio * (n - k) / (k + 1.0);
        k += 1.0;
        cumulative += probability;
      }
      return k;
    }
    case Distribution::Poisson: {
      const double u = rng.uniform();
      double probability = std::exp(-a), cumulative = probability;
      double k = 0.0;
      // The tail beyond mean + 40 sd is below 1e-300: the cap only guards rounding.
      const double last = a + 40.0 * std::sqrt(a) + 40.0;
      while (u >= cumulative && k < last) {
        k += 1.0;
        probability *= a / k;
        cumulative += probability;
      }
      return k;
    }
  }
  return 0.0;
}

double RandomVariable::mean() const {
  switch (distribution) {
    case Distribution::Constant:
      return a;
    case Distribution::Uniform:
      return 0.5 * (a + b);
    case Distribution::Exponential:
      return 1.0 / a;
    case Distribution::Normal:
      return a;
    case Distribution::Binomial:
      return a * b;
    case Distribution::Poisson:
      return a;
  }
  return 0.0;
}

double RandomVariable::variance() const {
  switch (distribution) {
    case Distribution::Constant:
      return 0.0;
    case Distribution::Uniform:
      if (discrete) {
        const double count = b - a + 1.0;
        return (count * count - 1.0) / 12.0;
      }
      return (b - a) * (b - a) / 12.0;
    case Distribution::Exponential:
      return 1.0 / (a * a);
    case Distribution::Normal:
      return b * b;
    case Distribution::Binomial:
      return a * b * (1.0 - b);
    case Distribution::Poisson:
      return a;
  }
  return 0.0;
}

namespace {

struct NamedDistribution {
  std::string_view name;
  Distribution distribution;
  int arity;
};
constexpr NamedDistribution kDistributions[] = {
    {"CONSTANT", Distribution::Constant, 1},       {"UNIFORM", Distribution::Uniform, 2},
    {"EXPONENTIAL", Distribution::Exponential, 1}, {"NORMAL", Distribution::Normal, 2},
    {"GAUSSIAN", Distribution::Normal, 2},         {"BINOMIAL", Distribution::Binomial, 2},
    {"POISSON", Distribution::Poisson, 1},
};

}  // namespace

bool distributionFromName(const std::string& upperName, Distribution& out) {
  for (const NamedDistribution& d : kDistributions)
    if (d.name == upperName) {
      out = d.distribution;
      return true;
    }
  return false;
}

const char* distributionName(Distribution distribution) {
  for (const NamedDistribution& d : kDistributions)
    if (d.distribution == distribution) return d.name.data();
  return "?";
}

int distributionArity(Distribution distribution) {
  for (const NamedDistribution& d : kDistributions)
    if (d.distribution == distribution) return d.arity;
  return 1;
}

std::string checkRandomVariable(const RandomVariable& v) {
  const bool isInteger = std::floor(v.a) == v.a && std::floor(v.b) == v.b;
  switch (v.distribution) {
    case Distribution::Constant:
      if (v.discrete && std::floor(v.a) != v.a) return "a DISCRETE constant must be an integer";
      return {};
    case Distribution::Uniform:
      if (v.b < v.a) return "UNIFORM(a, b) needs a <= b";
      if (v.discrete && !isInteger) return "a DISCRETE UNIFORM needs integer bounds";
      return {};
    case Distribution::Exponential:
      if (v.discrete) return "EXPONENTIAL is a CONTINUOUS distribution";
      if (!(v.a > 0.0)) return "EXPONENTIAL(rate) needs rate > 0";
      return {};
    case Distribution::Normal:
      if (v.discrete) return "NORMAL is a CONTINUOUS distribution";
      if (!(v.b >= 0.0)) return "NORMAL(mean, sd) needs sd >= 0";
      return {};
    case Distribution::Binomial:
      if (!v.discrete) return "BINOMIAL is a DISCRETE distribution";
      if (std::floor(v.a) != v.a || v.a < 0.0 || v.a > kMaxBinomialTrials)
        return "BINOMIAL(n, p) needs an integer n in 0..100000";
      if (!(v.b >= 0.0 && v.b <= 1.0)) return "BINOMIAL(n, p) needs p in 0..1";
      return {};
    case Distribution::Poisson:
      if (!v.discrete) return "POISSON is a DISCRETE distribution";
      if (!(v.a > 0.0 && v.a <= kMaxPoissonMean)) return "POISSON(mean) needs a mean in (0, 500]";
      return {};
  }
  return {};
}

}  // namespace eco
