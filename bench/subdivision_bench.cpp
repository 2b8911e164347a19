// Refinement and stencil application on n x n x n blocks of unit hexahedra.
#include <benchmark/benchmark.h>

#include "mesh/standard_cell.h"
#include "subdiv/mj_refiner.h"

namespace {

sculpt::CellComplex unitBlock(int n) {
  sculpt::CellComplex mesh;
  const int m = n + 1;
  auto id = [m](int i, int j, int k) { return uint32_t((k * m + j) * m + i); };
  mesh.positions.resize(m * m * m, 3);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) mesh.positions.row(id(i, j, k)) << i, j, k;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const uint32_t v[8] = {id(i, j, k),         id(i + 1, j, k),     id(i + 1, j + 1, k),
                               id(i, j + 1, k),     id(i, j, k + 1),     id(i + 1, j, k + 1),
                               id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        mesh.addCell(sculpt::standardCellFaces(sculpt::StandardCell::Hexahedron, v));
      }
  return mesh;
}

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

BENCHMARK_MAIN();
