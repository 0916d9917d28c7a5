// Skeleton and LOD0 mesh build for the paper's beech and pine (issue goal, one core:
// beech skeleton + LOD0 mesh < 2 ms, pine < 10 ms). Run: build/bench/tree_bench
#include <benchmark/benchmark.h>

#include "model/mesh/lod.hpp"
#include "model/mesh/tree_mesher.hpp"
#include "model/strand_model.hpp"

namespace {

const eco::Species& species(const char* name) {
  static eco::Species beech = eco::loadSpecies(ECOFOREST_DATA_DIR "/species/beech.toml");
  static eco::Species pine = eco::loadSpecies(ECOFOREST_DATA_DIR "/species/pine.toml");
  return std::string_view(name) == "beech" ? beech : pine;
}

void skeleton(benchmark::State& state, const char* name) {
  const eco::Species& s = species(name);
  std::size_t segments = 0;
  for (auto _ : state) {
    eco::TreeSkeleton tree = eco::buildStrandTree(s, {});
    segments = tree.segments.size();
    benchmark::DoNotOptimize(tree);
  }
  state.counters["segments/s"] = benchmark::Counter(static_cast<double>(segments),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}

void lod0Mesh(benchmark::State& state, const char* name) {
  const eco::Species& s = species(name);
  eco::TreeSkeleton tree = eco::buildStrandTree(s, {});
  std::size_t triangles = 0;
  for (auto _ : state) {
    eco::TreeMesh mesh = eco::buildLod(tree, s, 0);
    triangles = mesh.triangleCount();
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["triangles/s"] = benchmark::Counter(static_cast<double>(triangles),
                                                     benchmark::Counter::kIsIterationInvariantRate);
  state.counters["triangles"] = static_cast<double>(triangles);
}

// The goal: both steps together.
void skeletonAndLod0(benchmark::State& state, const char* name) {
  const eco::Species& s = species(name);
  for (auto _ : state) {
    eco::TreeSkeleton tree = eco::buildStrandTree(s, {});
    eco::TreeMesh mesh = eco::buildLod(tree, s, 0);
    benchmark::DoNotOptimize(mesh);
  }
}

// The same, as a tool building many trees runs it: skeleton and mesh arrays are reused
// from one tree to the next (the ...Into functions), so no fresh memory is page-faulted in.
void skeletonAndLod0Reused(benchmark::State& state, const char* name) {
  const eco::Species& s = species(name);
  eco::TreeSkeleton tree;
  eco::TreeMesh mesh;
  std::uint64_t seed = 1;
  for (auto _ : state) {
    eco::buildStrandTreeInto(s, {.seed = seed++}, tree);
    eco::buildLodInto(tree, s, 0, mesh);
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangleCount());
}

void lodMesh(benchmark::State& state, const char* name) {
  const eco::Species& s = species(name);
  eco::TreeSkeleton tree = eco::buildStrandTree(s, {});
  for (auto _ : state)
    benchmark::DoNotOptimize(eco::buildLod(tree, s, static_cast<int>(state.range(0))));
}

}  // namespace

BENCHMARK_CAPTURE(skeleton, beech, "beech")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(skeleton, pine, "pine")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lod0Mesh, beech, "beech")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lod0Mesh, pine, "pine")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(skeletonAndLod0, beech, "beech")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(skeletonAndLod0, pine, "pine")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(skeletonAndLod0Reused, beech, "beech")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(skeletonAndLod0Reused, pine, "pine")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(lodMesh, pine, "pine")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
