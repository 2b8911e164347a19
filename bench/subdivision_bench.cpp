// Refinement and stencil application on n x n x n blocks of unit hexahedra.
#include <benchmark/benchmark.h>

#include "unit_block.h"
#include "subdiv/mj_refiner.h"

namespace {

using sculpt::bench::unitBlock;

void BM_SubdivideBlock(benchmark::State& state) {
  const sculpt::CellComplex mesh = unitBlock(int(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(sculpt::subdivide(mesh, 2));
}
BENCHMARK(BM_SubdivideBlock)->Arg(4)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_BuildTopologyLevel2(benchmark::State& state) {
  const auto subdivision = sculpt::subdivide(unitBlock(int(state.range(0))), 2);
  for (auto _ : state) benchmark::DoNotOptimize(sculpt::buildTopology(subdivision->finest()));
}
BENCHMARK(BM_BuildTopologyLevel2)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_ApplyChain(benchmark::State& state) {
  const sculpt::CellComplex mesh = unitBlock(int(state.range(0)));
  const auto subdivision = sculpt::subdivide(mesh, 2);
  sculpt::Points out;
  for (auto _ : state) subdivision->chain.apply(mesh.positions, out);
  state.counters["vertices"] = double(out.rows());
}
BENCHMARK(BM_ApplyChain)->Arg(10)->Arg(12)->Unit(benchmark::kMicrosecond);

void BM_ApplyComposed(benchmark::State& state) {
  const sculpt::CellComplex mesh = unitBlock(int(state.range(0)));
  const auto subdivision = sculpt::subdivide(mesh, 2);
  sculpt::Points out;
  for (auto _ : state) subdivision->stencils.apply(mesh.positions, out);
  state.counters["vertices"] = double(out.rows());
}
BENCHMARK(BM_ApplyComposed)->Arg(10)->Arg(12)->Unit(benchmark::kMicrosecond);

}  // namespace
