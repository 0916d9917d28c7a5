#include "model/lsystem/deriver.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/error.hpp"
#include "core/random.hpp"
#include "model/lsystem/turtle.hpp"

namespace eco {
namespace {

constexpr std::uint64_t kDerivePurpose = purpose("lsystem.derive");
// Input modules per parallel chunk: a fixed size, so keys and results never depend on the
// thread count, and large enough that the final concatenation is cheap.
constexpr std::size_t kChunk = 1 << 15;
// How often (input modules) a chunk adds its output to the shared count checked by the cap.
constexpr std::size_t kCapCheckInterval = 1024;

// For each bracket of the string, the index of its partner; -1 for other modules and for
// brackets without one.
std::vector<std::int64_t> matchBrackets(const ModuleString& s) {
  std::vector<std::int64_t> match(s.size(), -1);
  std::vector<std::int64_t> open;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.modules[i].symbol == '[') {
      open.push_back(static_cast<std::int64_t>(i));
    } else if (s.modules[i].symbol == ']' && !open.empty()) {
      match[i] = open.back();
      match[static_cast<std::size_t>(open.back())] = static_cast<std::int64_t>(i);
      open.pop_back();
    }
  }
  return match;
}

class StepDeriver {
 public:
  StepDeriver(const LSystem& system, const ModuleString& in, int numIt, int maxIt,
              std::uint64_t seed, const std::vector<std::int64_t>& brackets,
              std::atomic<std::size_t>& produced, std::size_t maxModules)
      : system_(system),
        in_(in),
        brackets_(brackets),
        produced_(produced),
        maxModules_(maxModules),
        stepKey_(streamKey(seed, static_cast<std::uint64_t>(numIt), kDerivePurpose)),
        slots_(64),
        byRule_(system.productions.size(), 0) {
    env_.numIt = numIt;
    env_.maxIt = maxIt;
    for (const Production& p : system.productions)
      slots_.resize(std::max(slots_.size(), static_cast<std::size_t>(p.slotCount)));
    env_.slots = slots_.data();
    // A symbol whose first production has no parameters, context or condition and a
    // constant successor rewrites every bare module of it the same way: copy it directly.
    constantRule_.fill(-1);
    for (std::size_t symbol = 0; symbol < kSymbolCount; ++symbol) {
      const auto& rules = system.rulesBySymbol[symbol];
      if (rules.empty()) continue;
      const Production& p = system.productions[rules.front()];
      if (p.strict.slots.empty() && !p.hasContext() && !p.condition && p.successor.constant)
        constantRule_[symbol] = static_cast<std::int32_t>(rules.front());
    }
  }

  // Derives modules [begin, end) of the input into `out`. Returns false when the shared
  // module count passed the cap (the caller reports it).
  bool derive(std::size_t begin, std::size_t end, ModuleString& out) {
    std::size_t reported = out.size();
    for (std::size_t i = begin; i < end; ++i) {
      deriveModule(in_, i, true, moduleKey(i), out);
      if ((i - begin) % kCapCheckInterval == kCapCheckInterval - 1 || i + 1 == end) {
        const std::size_t total = produced_ += out.size() - reported;
        reported = out.size();
        if (total > maxModules_) return false;
      }
    }
    return true;
  }

  const std::vector<std::size_t>& modulesByRule() const { return byRule_; }

 private:
  std::uint64_t moduleKey(std::size_t i) const {
    return system_.variables.empty() ? 0 : streamKey(stepKey_, i);
  }

  void deriveModule(const ModuleString& s, std::size_t i, bool withContext, std::uint64_t key,
                    ModuleString& out) {
    const Module& m = s.modules[i];
    if (m.body != kNoBody) return deriveControl(s, m, key, out);
    const std::vector<std::uint32_t>& rules = system_.rulesBySymbol[m.symbol];
    if (m.paramCount == 0) {  // the commonest cases: bare symbols of context-free systems
      if (rules.empty()) {
        out.modules.push_back(
            {m.symbol, 0, static_cast<std::uint32_t>(out.params.size()), kNoBody});
        return;
      }
      if (const std::int32_t r = constantRule_[m.symbol]; r >= 0) {
        const StringTemplate& successor =
            system_.productions[static_cast<std::size_t>(r)].successor;
        instantiate(successor, env_, out);
        byRule_[static_cast<std::size_t>(r)] += successor.prebuilt.size();
        return;
      }
    }
    if (!rules.empty()) {
      const VariableDeviates deviates(system_.variables, key);
      env_.deviates = &deviates;
      const double* params = s.paramsOf(m);
      for (std::uint32_t r : rules) {
        const Production& p = system_.productions[r];
        if (p.strict.slots.size() != m.paramCount) continue;
        for (std::size_t k = 0; k < p.strict.slots.size(); ++k)
          slots_[p.strict.slots[k]] = params[k];
        if (p.hasContext() && (!withContext || !matchLeft(s, i, p) || !matchRight(s, i, p)))
          continue;
        if (p.condition && !holds(*p.condition, env_)) continue;
        const std::size_t before = out.size();
        instantiate(p.successor, env_, out);
        byRule_[r] += out.size() - before;
        return;
      }
    }
    out.append(s, i);
  }

  // Switch derives one item of its list per step, Pendulum its whole list forward or
  // backward in turn, Repetition its body `count` times (docs/lsystems.md).
  void deriveControl(const ModuleString& s, const Module& m, std::uint64_t key, ModuleString& out) {
    const ModuleString& body = s.bodies[m.body];
    const double* params = s.paramsOf(m);
    const auto n = static_cast<std::int64_t>(body.size());
    auto itemKey = [&](std::uint64_t copy, std::size_t item) {
      return system_.variables.empty() ? 0 : streamKey(key, copy, item);
    };
    if (m.symbol == kSwitch) {
      const std::int64_t next = (static_cast<std::int64_t>(std::llround(params[0])) % n + n) % n;
      deriveModule(body, static_cast<std::size_t>(next), false, itemKey(0, next), out);
      const double after = static_cast<double>((next + 1) % n);
      out.add(kSwitch, &after, 1);
    } else if (m.symbol == kPendulum) {
      const bool forward = params[0] >= 0.0;
      for (std::int64_t k = 0; k < n; ++k) {
        const auto item = static_cast<std::size_t>(forward ? k : n - 1 - k);
        deriveModule(body, item, false, itemKey(0, item), out);
      }
      const double after = forward ? -1.0 : 1.0;
      out.add(kPendulum, &after, 1);
    } else {  // Repetition: consumed
      // One module may not blow past the cap before the next check: test the count first.
      const double count = std::max(0.0, std::round(params[0]));
      if (!(count * static_cast<double>(body.size()) <= static_cast<double>(maxModules_)))
        throw InputError({system_.file, 0, ""},
                         "derivation step " + std::to_string(static_cast<int>(env_.numIt)) +
                             ": @Repetition(" + std::to_string(params[0]) + ") of " +
                             std::to_string(body.size()) + " modules would make more than " +
                             std::to_string(maxModules_) + " modules (the MAXMODULES cap)");
      const auto copies = static_cast<long long>(count);
      for (long long c = 0; c < copies; ++c)
        for (std::size_t item = 0; item < body.size(); ++item)
          deriveModule(body, item, false, itemKey(static_cast<std::uint64_t>(c), item), out);
      return;
    }
    out.modules.back().body = static_cast<std::uint32_t>(out.bodies.size());
    out.bodies.push_back(body);
  }

  bool bind(const ModuleString& s, std::size_t at, const PatternModule& want) {
    const Module& m = s.modules[at];
    if (m.symbol != want.symbol || m.paramCount != want.slots.size()) return false;
    const double* params = s.paramsOf(m);
    for (std::size_t k = 0; k < want.slots.size(); ++k) slots_[want.slots[k]] = params[k];
    return true;
  }

  // ABOP's left context for bracketed strings: walking left skips enclosed sub-branches
  // ("[...]" seen from their end) and steps from a branch's '[' to its parent.
  bool matchLeft(const ModuleString& s, std::size_t i, const Production& p) {
    auto pos = static_cast<std::int64_t>(i) - 1;
    for (auto k = static_cast<std::int64_t>(p.left.size()) - 1; k >= 0; --k) {
      for (;;) {
        if (pos < 0) return false;
        const Symbol symbol = s.modules[static_cast<std::size_t>(pos)].symbol;
        if (symbol == ']') {
          const std::int64_t open = brackets_[static_cast<std::size_t>(pos)];
          if (open < 0) return false;
          pos = open - 1;
        } else if (symbol == '[' || system_.ignored[symbol]) {
          --pos;
        } else {
          break;
        }
      }
      if (!bind(s, static_cast<std::size_t>(pos), p.left[static_cast<std::size_t>(k)]))
        return false;
      --pos;
    }
    return true;
  }

  // ABOP's right context: a module of the context may sit after whole sub-branches, which
  // are skipped; the context never leaves the branch (a ']' not in the context ends it).
  // A ']' in the context skips the rest of the current branch.
  bool matchRight(const ModuleString& s, std::size_t i, const Production& p) {
    const auto n = static_cast<std::int64_t>(s.size());
    auto pos = static_cast<std::int64_t>(i) + 1;
    for (const PatternModule& want : p.right) {
      if (want.symbol == ']') {
        while (pos < n && s.modules[static_cast<std::size_t>(pos)].symbol != ']') {
          if (s.modules[static_cast<std::size_t>(pos)].symbol == '[') {
            const std::int64_t close = brackets_[static_cast<std::size_t>(pos)];
            if (close < 0) return false;
            pos = close;
          }
          ++pos;
        }
        if (pos >= n) return false;
        ++pos;
        continue;
      }
      for (;;) {
        if (pos >= n) return false;
        const Symbol symbol = s.modules[static_cast<std::size_t>(pos)].symbol;
        if (symbol == '[' && want.symbol != '[') {
          const std::int64_t close = brackets_[static_cast<std::size_t>(pos)];
          if (close < 0) return false;
          pos = close + 1;
        } else if (symbol == ']') {
          return false;
        } else if (symbol != want.symbol && system_.ignored[symbol]) {
          ++pos;
        } else {
          break;
        }
      }
      if (!bind(s, static_cast<std::size_t>(pos), want)) return false;
      ++pos;
    }
    return true;
  }

  const LSystem& system_;
  const ModuleString& in_;
  const std::vector<std::int64_t>& brackets_;
  std::atomic<std::size_t>& produced_;
  std::size_t maxModules_;
  std::uint64_t stepKey_;
  std::vector<double> slots_;
  std::vector<std::size_t> byRule_;
  std::array<std::int32_t, kSymbolCount> constantRule_;
  EvalEnv env_;
};

[[noreturn]] void reportExplosion(const LSystem& system, int numIt, std::size_t maxModules,
                                  const std::vector<std::size_t>& byRule) {
  const auto worst = std::max_element(byRule.begin(), byRule.end());
  std::string message = "derivation step " + std::to_string(numIt) + " makes more than " +
                        std::to_string(maxModules) + " modules (the MAXMODULES cap)";
  if (worst == byRule.end() || *worst == 0)
    throw InputError({system.file, 0, ""}, message + "; lower the iterations");
  const Production& p = system.productions[static_cast<std::size_t>(worst - byRule.begin())];
  throw InputError({system.file, p.line, ""},
                   message + ": the production '" + p.text + "' exploded (it made " +
                       std::to_string(*worst) +
                       " modules before the cap stopped it); lower the iterations or raise "
                       "MAXMODULES");
}

// Moves the chunks' strings into one, rebasing parameter and body indices.
void concatenate(std::vector<ModuleString>& parts, std::size_t count, ModuleString& out) {
  std::vector<std::size_t> moduleStart(count + 1, 0), paramStart(count + 1, 0),
      bodyStart(count + 1, 0);
  for (std::size_t c = 0; c < count; ++c) {
    moduleStart[c + 1] = moduleStart[c] + parts[c].modules.size();
    paramStart[c + 1] = paramStart[c] + parts[c].params.size();
    bodyStart[c + 1] = bodyStart[c] + parts[c].bodies.size();
  }
  out.modules.resize(moduleStart.back());
  out.params.resize(paramStart.back());
  out.bodies.resize(bodyStart.back());
  tbb::parallel_for(std::size_t{0}, count, [&](std::size_t c) {
    const ModuleString& part = parts[c];
    const auto paramBase = static_cast<std::uint32_t>(paramStart[c]);
    const auto bodyBase = static_cast<std::uint32_t>(bodyStart[c]);
    Module* target = out.modules.data() + moduleStart[c];
    for (const Module& m : part.modules) {
      *target = m;
      target->firstParam += paramBase;
      if (m.body != kNoBody) target->body += bodyBase;
      ++target;
    }
    std::copy(part.params.begin(), part.params.end(), out.params.begin() + paramStart[c]);
    std::move(parts[c].bodies.begin(), parts[c].bodies.end(), out.bodies.begin() + bodyStart[c]);
  });
}

}  // namespace

ModuleString instantiateAxiom(const LSystem& system, std::uint64_t seed, int maxIt) {
  const VariableDeviates deviates(system.variables, streamKey(seed, 0, kDerivePurpose));
  EvalEnv env;
  env.maxIt = maxIt;
  env.deviates = &deviates;
  ModuleString axiom;
  instantiate(system.axiom, env, axiom);
  return axiom;
}

namespace {

// One step into `out`; `parts` holds the chunks' strings and keeps their memory from step
// to step; `growth` (output per input module of the last step) sizes the buffers.
void deriveStepWith(const LSystem& system, const ModuleString& in, ModuleString& out, int numIt,
                    int maxIt, std::uint64_t seed, std::size_t maxModules, double growth,
                    std::vector<ModuleString>& parts) {
  out.clear();
  const std::vector<std::int64_t> brackets =
      system.usesContext ? matchBrackets(in) : std::vector<std::int64_t>{};
  std::atomic<std::size_t> produced{0};
  const std::size_t chunks = (in.size() + kChunk - 1) / kChunk;
  auto expected = [&](std::size_t inputs) {
    return std::min(maxModules, static_cast<std::size_t>(static_cast<double>(inputs) * growth));
  };
  // One thread gains nothing from chunks and would copy every module twice. The result
  // is the same either way: deviates are keyed by module position, not by chunk.
  if (chunks <= 1 || tbb::this_task_arena::max_concurrency() == 1) {
    out.modules.reserve(expected(in.size()));
    StepDeriver deriver(system, in, numIt, maxIt, seed, brackets, produced, maxModules);
    if (!deriver.derive(0, in.size(), out))
      reportExplosion(system, numIt, maxModules, deriver.modulesByRule());
    return;
  }
  if (parts.size() < chunks) parts.resize(chunks);
  std::vector<std::vector<std::size_t>> byRule(chunks);
  std::atomic<bool> exploded{false};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t c = range.begin(); c < range.end(); ++c) {
                        if (exploded) return;
                        StepDeriver deriver(system, in, numIt, maxIt, seed, brackets, produced,
                                            maxModules);
                        const std::size_t begin = c * kChunk;
                        const std::size_t end = std::min(in.size(), begin + kChunk);
                        parts[c].clear();
                        parts[c].modules.reserve(expected(end - begin));
                        if (!deriver.derive(begin, end, parts[c])) exploded = true;
                        byRule[c] = deriver.modulesByRule();
                      }
                    });
  if (exploded) {
    std::vector<std::size_t> total(system.productions.size(), 0);
    for (const auto& counts : byRule)
      for (std::size_t r = 0; r < counts.size(); ++r) total[r] += counts[r];
    reportExplosion(system, numIt, maxModules, total);
  }
  concatenate(parts, chunks, out);
}

}  // namespace

void deriveStep(const LSystem& system, const ModuleString& in, ModuleString& out, int numIt,
                int maxIt, std::uint64_t seed, std::size_t maxModules) {
  std::vector<ModuleString> parts;
  deriveStepWith(system, in, out, numIt, maxIt, seed, maxModules, 2.0, parts);
}

bool applyPruneModules(ModuleString& string) {
  const auto first = std::find_if(string.modules.begin(), string.modules.end(),
                                  [](const Module& m) { return m.symbol == kPrune; });
  if (first == string.modules.end()) return false;
  ModuleString kept;
  kept.modules.reserve(string.size());
  kept.params.reserve(string.params.size());
  for (std::size_t i = 0; i < string.size(); ++i) {
    if (string.modules[i].symbol != kPrune) {
      kept.append(string, i);
      continue;
    }
    i = branchEnd(string, i + 1) - 1;  // skip the rest of the branch; keep its ']'
  }
  string = std::move(kept);
  return true;
}

ModuleString derive(const LSystem& system, const DeriveOptions& options, DeriveStats* stats) {
  const int iterations = options.iterations.value_or(system.iterations);
  ECO_ASSERT(iterations >= 0 && iterations <= kMaxIterations, "iterations=" << iterations);
  const std::size_t maxModules = options.maxModules.value_or(system.maxModules);
  ModuleString current = instantiateAxiom(system, options.seed, iterations);
  ModuleString next;
  std::vector<ModuleString> parts;
  double growth = 2.0;
  if (stats) *stats = {};
  for (int step = 1; step <= iterations; ++step) {
    deriveStepWith(system, current, next, step, iterations, options.seed, maxModules, growth,
                   parts);
    if (!current.modules.empty())
      growth = 1.05 * static_cast<double>(next.size()) / static_cast<double>(current.size());
    if (stats) {
      ++stats->steps;
      stats->modulesRewritten += current.size();
      stats->modulesProduced += next.size();
    }
    std::swap(current, next);
    if (system.usesPrune) applyPruneModules(current);
    if (system.usesQueries || system.prune.shape != PruneShape::None)
      applyEnvironment(system, current);
  }
  return current;
}

}  // namespace eco
