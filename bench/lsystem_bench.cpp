// RL-system derivation and turtle interpretation (issue goal: rewrite at least ten times
// the 3-12 million symbols per second of the JavaScript library `lindenmayer`).
// Counters: modules/s = input modules rewritten per second over all steps; produced/s =
// output modules written per second; segments/s for the turtle.
// Run: build/bench/lsystem_bench   (one core: taskset -c 0 build/bench/lsystem_bench)
#include <map>
#include <string>

#include <benchmark/benchmark.h>

#include "model/lsystem/deriver.hpp"
#include "model/lsystem/parser.hpp"
#include "model/lsystem/turtle.hpp"

namespace {

const eco::LSystem& grammar(const std::string& name) {
  static std::map<std::string, eco::LSystem> loaded;
  auto it = loaded.find(name);
  if (it == loaded.end())
    it = loaded.emplace(name, eco::loadLSystem(ECOFOREST_DATA_DIR "/lsystems/" + name + ".lsys"))
             .first;
  return it->second;
}

void derive(benchmark::State& state, const char* name) {
  const eco::LSystem& system = grammar(name);
  eco::DeriveOptions options;
  options.iterations = static_cast<int>(state.range(0));
  eco::DeriveStats stats;
  for (auto _ : state) {
    eco::ModuleString s = eco::derive(system, options, &stats);
    benchmark::DoNotOptimize(s);
  }
  state.counters["modules/s"] = benchmark::Counter(static_cast<double>(stats.modulesRewritten),
                                                   benchmark::Counter::kIsIterationInvariantRate);
  state.counters["produced/s"] = benchmark::Counter(static_cast<double>(stats.modulesProduced),
                                                    benchmark::Counter::kIsIterationInvariantRate);
  state.counters["modules"] = static_cast<double>(stats.modulesProduced);
}

void interpret(benchmark::State& state, const char* name) {
  const eco::LSystem& system = grammar(name);
  eco::DeriveOptions options;
  options.iterations = static_cast<int>(state.range(0));
  const eco::ModuleString s = eco::derive(system, options);
  std::size_t segments = 0;
  for (auto _ : state) {
    eco::TreeSkeleton tree = eco::interpretTree(system, s);
    segments = tree.segments.size();
    benchmark::DoNotOptimize(tree);
  }
  state.counters["segments/s"] = benchmark::Counter(static_cast<double>(segments),
                                                    benchmark::Counter::kIsIterationInvariantRate);
  state.counters["modules/s"] = benchmark::Counter(static_cast<double>(s.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

// Context-free bracketed OL-systems, ABOP Fig. 1.24.
BENCHMARK_CAPTURE(derive, abop_1_24a, "abop_1_24a")->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(derive, abop_1_24c, "abop_1_24c")->Arg(6)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(derive, abop_1_24d, "abop_1_24d")->Arg(11)->Unit(benchmark::kMillisecond);
// Stochastic (a random variable per module), parametric with expressions, context-sensitive.
BENCHMARK_CAPTURE(derive, abop_1_27, "abop_1_27")->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(derive, abop_2_6, "abop_2_6")->Arg(18)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(interpret, abop_1_24a, "abop_1_24a")->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(interpret, abop_2_6, "abop_2_6")->Arg(16)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
