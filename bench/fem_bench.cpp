// The parts of a FEM step on assets/block3.json at simulation level K (the argument): the
// elastic element pass (rotations and forces), the tricubic kernel alone with its rest data in
// the cache and streamed, the projections A p and A^T f, and the polar rotations; on an 8^3
// block, the reduced mass products, the preconditioner's solve and the first step's set-up.
// Per-element and per-node figures come as counters; threads as for the program
// (SCULPT_THREADS).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <optional>
#include <random>
#include <string>

#include "fem/fem_model.h"
#include "fem/mass_matrix.h"
#include "fem/polar_rotation.h"
#include "fem/tricubic_kernel.h"
#include "sim/linear_stiffness.h"
#include "sim/rest_stiffness.h"
#include "sim/standard_forms.h"
#include "sim/system_preconditioner.h"
#include "unit_block.h"

namespace {

using namespace sculpt;

// block3 at level K with its nodes twisted a little about the vertical axis (every element
// gets a rotation and a strain, as in a running simulation).
struct Block3 {
  std::optional<FemModel> model;
  Points nodes;
  explicit Block3(int level) {
    FemSetup setup;
    setup.level = level;
    std::string error;
    model = FemModel::create(bench::unitBlock(3), setup, &error);
    if (!model) throw std::runtime_error(error);
    const Points& rest = model->mesh().restNodes;
    nodes = rest;
    for (Eigen::Index n = 0; n < rest.rows(); ++n) {
      const double angle = 0.05 * rest(n, 1);
      const Eigen::Matrix3d R =
          Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
      nodes.row(n) = (R * (rest.row(n).transpose() - Eigen::Vector3d(1.5, 0, 1.5)) +
                      Eigen::Vector3d(1.5, 0, 1.5))
                         .transpose();
    }
  }
};

Block3& block3(int level) {
  static Block3 two(2), three(3);
  return level == 2 ? two : three;
}

void BM_ElasticPass(benchmark::State& state) {
  Block3& block = block3(int(state.range(0)));
  ElasticKernel& elastic = block.model->elastic();
  Points gradient = Points::Zero(block.nodes.rows(), 3);
  for (auto _ : state) {
    gradient.setZero();
    elastic.updateRotationsAndAddGradient(block.nodes, gradient);
    benchmark::DoNotOptimize(gradient.data());
  }
  const double elements = block.model->mesh().numElements();
  state.counters["ns_per_element"] =
      benchmark::Counter(elements, benchmark::Counter::kIsIterationInvariantRate |
                                       benchmark::Counter::kInvert);
  state.counters["elements"] = elements;
}
BENCHMARK(BM_ElasticPass)->Arg(2)->Arg(3)->Unit(benchmark::kMicrosecond);

// One element's displacements (small, random), its rotation and a place for its gradient.
struct KernelInput {
  alignas(64) double u[192];
  alignas(64) double gradient[192];
  Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  KernelInput() {
    std::mt19937_64 rng(1);
    std::normal_distribution<double> noise(0.0, 1e-3);
    for (double& v : u) v = noise(rng);
  }
};

// The tricubic kernel on one thread over every tricubic element's rest data (range(1) = 0:
// as laid out for the model, streamed from memory at K = 3) or over one element's data again
// and again (range(1) = 1: in the cache). The difference is the cost of the data traffic.
void BM_TricubicKernel(benchmark::State& state) {
  Block3& block = block3(int(state.range(0)));
  const FemMesh& mesh = block.model->mesh();
  const bool hot = state.range(1) == 1;
  const uint32_t count = mesh.numTricubic();
  // Rest data packed as the elastic pass packs it (every element with its 16 blocks of inverse
  // Jacobians).
  const int size = tricubicRestSize(false);
  std::vector<double> rest(size_t(count) * size_t(size));
  for (uint32_t e = 0; e < count; ++e) {
    double* packed = rest.data() + size_t(e) * size_t(size);
    packTricubicInverseJacobians(mesh.tricubicInverseJacobian.data() + size_t(e) * 64, false,
                                 packed);
    packTricubicMaterial(mesh.gaussVolume.data() + size_t(e) * 64,
                         mesh.gaussLame.data() + size_t(e) * 64, false, packed);
  }
  KernelInput in;
  for (auto _ : state) {
    for (uint32_t e = 0; e < count; ++e) {
      const double* data = rest.data() + size_t(hot ? 0 : e) * size_t(size);
      const double* next = rest.data() + size_t(hot || e + 1 == count ? 0 : e + 1) * size_t(size);
      const TricubicPacked packed = tricubicPackedView(data, false, next, size);
      benchmark::DoNotOptimize(
          tricubicElementKernel(in.u, packed, in.R, true, false, in.gradient));
    }
  }
  state.counters["ns_per_element"] = benchmark::Counter(
      count, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TricubicKernel)->Args({2, 0})->Args({2, 1})->Args({3, 0})->Args({3, 1})
    ->Unit(benchmark::kMicrosecond);

// One affine element aligned with the axes (a cube of block3's interior at K = 2), its rest data
// packed as the elastic pass packs it; empty `rest` when block3 has none.
struct AxisAlignedElement {
  std::vector<double> rest;
  int8_t rows[3] = {0, 1, 2};
  AxisAlignedElement() {
    const FemMesh& mesh = block3(2).model->mesh();
    for (uint32_t e = 0; e < mesh.numTricubic(); ++e) {
      const Eigen::Matrix3d* J = mesh.tricubicInverseJacobian.data() + size_t(e) * 64;
      if (!affineInverseJacobians(J) || !axisAlignedRows(J[0], rows)) continue;
      rest.resize(size_t(tricubicRestSize(true)));
      packTricubicInverseJacobians(J, true, rest.data());
      packTricubicMaterial(mesh.gaussVolume.data() + size_t(e) * 64,
                           mesh.gaussLame.data() + size_t(e) * 64, true, rest.data());
      return;
    }
  }
};

// The kernel on that element, in the cache, through the general 3x3 inverse Jacobian
// (range(0) = 0) or through its one nonzero per column (range(0) = 1, as the elastic pass runs
// such elements).
void BM_TricubicKernelAxisAligned(benchmark::State& state) {
  const AxisAlignedElement element;
  if (element.rest.empty()) {
    state.SkipWithError("block3 has no axis-aligned tricubic element");
    return;
  }
  const TricubicPacked packed = tricubicPackedView(element.rest.data(), true, element.rest.data(),
                                                   0, state.range(0) == 1 ? element.rows : nullptr);
  KernelInput in;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tricubicElementKernel(in.u, packed, in.R, true, false, in.gradient));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_TricubicKernelAxisAligned)->Arg(0)->Arg(1)->Unit(benchmark::kNanosecond);

// The inversion barrier's cost where no Gauss point is below its threshold (the usual case), on
// the same element: without the barrier (range(0) = 0), with it in a gradient pass that records
// the states (1, as a step's first pass runs), and in a Hessian product of an element with no
// recorded state (2).
void BM_TricubicKernelBarrierCheck(benchmark::State& state) {
  const AxisAlignedElement element;
  if (element.rest.empty()) {
    state.SkipWithError("block3 has no axis-aligned tricubic element");
    return;
  }
  const TricubicPacked packed =
      tricubicPackedView(element.rest.data(), true, element.rest.data(), 0, element.rows);
  const InversionBarrier settings;
  alignas(64) double record[9 * 64];
  const int mode = int(state.range(0));
  KernelInput in;
  for (auto _ : state) {
    BarrierArgs args;
    if (mode >= 1) args.settings = &settings;
    if (mode == 1) args.record = record;
    benchmark::DoNotOptimize(tricubicElementKernel(in.u, packed, in.R, mode != 2, false,
                                                   in.gradient, mode == 0 ? nullptr : &args));
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_TricubicKernelBarrierCheck)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kNanosecond);

void BM_NodesFromControl(benchmark::State& state) {
  Block3& block = block3(int(state.range(0)));
  Points nodes;
  for (auto _ : state) {
    block.model->nodesFromControl(block.model->restControl(), nodes);
    benchmark::DoNotOptimize(nodes.data());
  }
  state.counters["nodes"] = double(block.model->numNodes());
}
BENCHMARK(BM_NodesFromControl)->Arg(2)->Arg(3)->Unit(benchmark::kMicrosecond);

void BM_AddToControl(benchmark::State& state) {
  Block3& block = block3(int(state.range(0)));
  Points control = Points::Zero(block.model->numControlPoints(), 3);
  for (auto _ : state) {
    block.model->addToControl(block.nodes, control);
    benchmark::DoNotOptimize(control.data());
  }
  state.counters["nodes"] = double(block.model->numNodes());
}
BENCHMARK(BM_AddToControl)->Arg(2)->Arg(3)->Unit(benchmark::kMicrosecond);

// An 8^3 block at K = 1: 729 control points, about the default bunny's 571.
const std::optional<FemModel>& block8() {
  static const std::optional<FemModel> model = [] {
    FemSetup setup;
    setup.level = 1;
    std::string error;
    return FemModel::create(bench::unitBlock(8), setup, &error);
  }();
  return model;
}

// The block, or null with the benchmark marked as failed when it did not build.
const FemModel* block8(benchmark::State& state) {
  const std::optional<FemModel>& model = block8();
  if (!model) state.SkipWithError("the 8^3 block did not build");
  return model ? &*model : nullptr;
}

// Its reduced mass matrix applied to the control points' positions, with the step's worker
// threads: a CG iteration applies the inertia's and the damping's.
void BM_ApplyReducedMass(benchmark::State& state) {
  const FemModel* model = block8(state);
  if (!model) return;
  const SparseMatrix& mass = model->reducedMass();
  const Points& x = model->restControl();
  for (auto _ : state) {
    Points y = applyScalarMatrix(mass, x);
    benchmark::DoNotOptimize(y.data());
  }
  state.counters["nonzeros"] = double(mass.nonZeros());
}
BENCHMARK(BM_ApplyReducedMass)->Unit(benchmark::kMicrosecond);

// The first implicit step's set-up on the same block: the reduced mass A^T M A (the inertia's
// and the damping's matrices; made whole again only when most of the density changes) and the
// preconditioner's stand-in stiffness K~lin, with the step's worker threads.
void BM_ReducedMassMatrix(benchmark::State& state) {
  const FemModel* model = block8(state);
  if (!model) return;
  for (auto _ : state) {
    SparseMatrix mass =
        reducedNodeMatrix(model->mesh(), model->stencilMatrix(), MassField::Density);
    benchmark::DoNotOptimize(mass.valuePtr());
  }
}
BENCHMARK(BM_ReducedMassMatrix)->Unit(benchmark::kMillisecond);

void BM_StandInStiffness(benchmark::State& state) {
  const FemModel* model = block8(state);
  if (!model) return;
  for (auto _ : state) {
    SparseMatrix stiffness = reducedLinearStiffness(*model);
    benchmark::DoNotOptimize(stiffness.valuePtr());
  }
}
BENCHMARK(BM_StandInStiffness)->Unit(benchmark::kMillisecond);

// The elements' own rest stiffness on the same block, what the preconditioner's second factor is
// made from: every tricubic element shares one pair of parts, so this is mostly its assembly.
void BM_RestStiffness(benchmark::State& state) {
  const FemModel* model = block8(state);
  if (!model) return;
  const FemMesh& mesh = model->mesh();
  for (auto _ : state) {
    SparseMatrix stiffness = reducedRestStiffness(mesh, mesh.gaussLame, model->stencilMatrix());
    benchmark::DoNotOptimize(stiffness.valuePtr());
  }
}
BENCHMARK(BM_RestStiffness)->Unit(benchmark::kMillisecond);

// One solve of the implicit step's preconditioner (S = M~/h^2 + K~lin at h = 1/60, every
// coordinate free) on the same block, with the step's worker threads: a CG iteration makes one.
void BM_PreconditionerSolve(benchmark::State& state) {
  const FemModel* model = block8(state);
  if (!model) return;
  std::vector<int> dofs(size_t(3 * model->numControlPoints()));
  for (size_t k = 0; k < dofs.size(); ++k) dofs[k] = int(k);
  SystemPreconditioner preconditioner;
  if (!preconditioner.update(*model, 3600, 0, 1, dofs)) {
    state.SkipWithError("the preconditioner did not factor");
    return;
  }
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(Eigen::Index(dofs.size()), -1.0, 1.0);
  Eigen::VectorXd z;
  for (auto _ : state) {
    preconditioner.apply(r, z);
    benchmark::DoNotOptimize(z.data());
  }
  state.counters["factor_nonzeros"] = double(preconditioner.stats().factorNonZeros);
}
BENCHMARK(BM_PreconditionerSolve)->Unit(benchmark::kMicrosecond);

// Warm-started polar rotations of 1,024 slightly rotated stretches: one at a time against four
// in the lanes of a vector.
void BM_PolarRotations(benchmark::State& state) {
  const int lanes = int(state.range(0));
  std::mt19937_64 rng(3);
  std::normal_distribution<double> small(0.0, 0.01);
  std::vector<Eigen::Matrix3d> F(1024), guess(1024), out(1024);
  for (size_t k = 0; k < F.size(); ++k) {
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(1.0 + small(rng), Eigen::Vector3d(small(rng), 1, small(rng)).normalized())
            .toRotationMatrix();
    Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
    S(0, 0) += 10 * small(rng);
    S(0, 1) = S(1, 0) = small(rng);
    F[k] = R * S;
    guess[k] = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  }
  for (auto _ : state) {
    for (size_t k = 0; k < F.size(); k += size_t(lanes)) {
      if (lanes == 1)
        out[k] = polarRotation(F[k], guess[k]);
      else
        polarRotations(&F[k], &guess[k], 4, &out[k]);
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["ns_per_rotation"] =
      benchmark::Counter(double(F.size()), benchmark::Counter::kIsIterationInvariantRate |
                                               benchmark::Counter::kInvert);
}
BENCHMARK(BM_PolarRotations)->Arg(1)->Arg(4)->Unit(benchmark::kMicrosecond);

}  // namespace
