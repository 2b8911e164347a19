#include "fem/elastic_kernel.h"

#include <array>

#include "fem/polar_rotation.h"
#include "fem/quadrature.h"
#include "fem/linear_kernel.h"
#include "fem/tricubic_kernel.h"
#include <algorithm>
#include "subdiv/tricubic_patch.h"
#include "util/parallel_for.h"

namespace sculpt {
namespace {

// B-spline values and derivatives at the 4 Gauss points and at the centre.
struct TricubicTables {
  double B[4][4], D[4][4];  // [gauss point][basis]
  double Bc[4], Dc[4];
  TricubicTables() {
    const QuadratureRule rule = gaussLegendre(4);
    for (int i = 0; i < 4; ++i) cubicBSplineBasis(rule.points[i], B[i], D[i]);
    cubicBSplineBasis(0.5, Bc, Dc);
  }
};
const TricubicTables& tables() {
  static const TricubicTables t;
  return t;
}

}  // namespace

ElasticKernel::ElasticKernel(const FemMesh& mesh)
    : mesh_(mesh), rotations_(mesh.numElements(), Eigen::Matrix3d::Identity()) {
  // Inverse Jacobians in the kernel's layout [i*4 + j][row*3 + col][k].
  const uint32_t numTricubic = mesh.numTricubic();
  tricubicInverseJacobian_.resize(size_t(numTricubic) * 576);
  for (uint32_t e = 0; e < numTricubic; ++e)
    for (int ij = 0; ij < 16; ++ij)
      for (int k = 0; k < 4; ++k) {
        const Eigen::Matrix3d& J = mesh.tricubicInverseJacobian[size_t(e) * 64 + ij * 4 + k];
        for (int rc = 0; rc < 9; ++rc)
          tricubicInverseJacobian_[size_t(e) * 576 + ij * 36 + rc * 4 + k] = J(rc / 3, rc % 3);
      }
  linearShapeGradient_.resize(size_t(mesh.numLinear()) * 192);
  for (uint32_t l = 0; l < mesh.numLinear(); ++l)
    for (int q = 0; q < 8; ++q) {
      const LinearShapeGradient& dN = mesh.linearShapeGradient[size_t(l) * 8 + q];
      for (int a = 0; a < 8; ++a)
        for (int c = 0; c < 3; ++c) linearShapeGradient_[size_t(l) * 192 + (a * 3 + c) * 8 + q] = dN(a, c);
    }
  refreshMaterial();
}

void ElasticKernel::refreshMaterial() {
  const size_t count = size_t(mesh_.numTricubic()) * 64;
  tricubicVolumeLambda_.resize(count);
  tricubicVolumeMu_.resize(count);
  for (size_t q = 0; q < count; ++q) {
    tricubicVolumeLambda_[q] = mesh_.gaussVolume[q] * mesh_.gaussLame[q].lambda;
    tricubicVolumeMu_[q] = mesh_.gaussVolume[q] * mesh_.gaussLame[q].mu;
  }
  const size_t linearCount = size_t(mesh_.numLinear()) * 8;
  linearVolumeLambda_.resize(linearCount);
  linearVolumeMu_.resize(linearCount);
  for (size_t k = 0; k < linearCount; ++k) {
    const size_t q = count + k;
    linearVolumeLambda_[k] = mesh_.gaussVolume[q] * mesh_.gaussLame[q].lambda;
    linearVolumeMu_[k] = mesh_.gaussVolume[q] * mesh_.gaussLame[q].mu;
  }
}

void ElasticKernel::resetRotations() {
  rotations_.assign(mesh_.numElements(), Eigen::Matrix3d::Identity());
}

void ElasticKernel::updateRotations(const Points& nodes) {
  const TricubicTables& T = tables();
  const uint32_t numTricubic = mesh_.numTricubic();
  parallelChunks(mesh_.numElements(), 256, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t e = begin; e < end; ++e) {
      Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
      if (e < numTricubic) {
        const auto& ids = mesh_.tricubicNodes[e];
        Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            for (int g = 0; g < 4; ++g) {
              const Eigen::Vector3d x = nodes.row(ids[a * 16 + b * 4 + g]).transpose();
              G.col(0) += T.Dc[a] * T.Bc[b] * T.Bc[g] * x;
              G.col(1) += T.Bc[a] * T.Dc[b] * T.Bc[g] * x;
              G.col(2) += T.Bc[a] * T.Bc[b] * T.Dc[g] * x;
            }
        F = G * mesh_.tricubicCentreInverseJacobian[e];
      } else {
        const uint32_t l = e - numTricubic;
        const auto& ids = mesh_.linearNodes[l];
        const LinearShapeGradient& dN = mesh_.linearCentreShapeGradient[l];
        for (int a = 0; a < kLinearNodes; ++a)
          F += nodes.row(ids[a]).transpose() * dN.row(a);
      }
      rotations_[e] = polarRotation(F);
    }
  });
}

double ElasticKernel::energy(const Points& nodes) const {
  return run(nodes, Mode::Gradient, nullptr, true);
}

void ElasticKernel::elementEnergies(const Points& nodes, std::vector<double>& energies) const {
  energies.assign(mesh_.numElements(), 0.0);
  run(nodes, Mode::Gradient, nullptr, true, energies.data());
}

void ElasticKernel::addGradient(const Points& nodes, Points& gradient) const {
  run(nodes, Mode::Gradient, &gradient, false);
}

void ElasticKernel::addHessianProduct(const Points& dx, Points& result) const {
  run(dx, Mode::HessianProduct, &result, false);
}

double ElasticKernel::run(const Points& x, Mode mode, Points* out, bool withEnergy,
                          double* perElement) const {
  const bool withRestTerm = mode == Mode::Gradient;  // x holds positions, not a direction
  const Points& rest = mesh_.restNodes;
  const uint32_t numTricubic = mesh_.numTricubic();
  const uint32_t numElements = mesh_.numElements();
  const unsigned workers = std::min<unsigned>(workerCount(), std::max(1u, numElements / 32));
  if (out) {
    workerBuffers_.resize(workers);
    for (Points& buffer : workerBuffers_) buffer.setZero(mesh_.numNodes(), 3);
  }
  std::vector<double> workerEnergy(workers, 0.0);
  // Equal work per worker: a tricubic element costs about three linear ones.
  const double totalCost = 3.0 * numTricubic + (numElements - numTricubic);
  auto chunkStart = [&](unsigned k) {
    const double target = totalCost * k / workers;
    return target <= 3.0 * numTricubic
               ? static_cast<uint32_t>(target / 3.0)
               : std::min(numElements, static_cast<uint32_t>(numTricubic + (target - 3.0 * numTricubic)));
  };

  parallelChunks(workers, 1, [&](uint32_t firstWorker, uint32_t lastWorker, unsigned) {
    for (uint32_t worker = firstWorker; worker < lastWorker; ++worker) {
      Points* sink = out ? &workerBuffers_[worker] : nullptr;
      double energy = 0;
      alignas(64) double ue[64 * 3];  // displacements (gradient) or the direction (Hessian)
      alignas(64) double ge[64 * 3];
      const uint32_t end = worker + 1 == workers ? numElements : chunkStart(worker + 1);
      for (uint32_t e = chunkStart(worker); e < end; ++e) {
        const Eigen::Matrix3d& R = rotations_[e];
        const bool tricubic = e < numTricubic;
        const uint32_t* ids = tricubic ? mesh_.tricubicNodes[e].data()
                                       : mesh_.linearNodes[e - numTricubic].data();
        const int count = tricubic ? kTricubicNodes : kLinearNodes;
        for (int n = 0; n < count; ++n)
          for (int c = 0; c < 3; ++c)
            ue[n * 3 + c] = withRestTerm ? x(ids[n], c) - rest(ids[n], c) : x(ids[n], c);
        if (sink) std::fill(ge, ge + count * 3, 0.0);
        double* gradient = sink ? ge : nullptr;
        double elementEnergy;
        if (tricubic) {
          const TricubicPacked packed{tricubicInverseJacobian_.data() + size_t(e) * 576,
                                      tricubicVolumeLambda_.data() + size_t(e) * 64,
                                      tricubicVolumeMu_.data() + size_t(e) * 64};
          elementEnergy = tricubicElementKernel(ue, packed, R, withRestTerm, withEnergy, gradient);
        } else {
          const size_t l = e - numTricubic;
          const LinearPacked packed{linearShapeGradient_.data() + l * 192,
                                    linearVolumeLambda_.data() + l * 8,
                                    linearVolumeMu_.data() + l * 8};
          elementEnergy = linearElementKernel(ue, packed, R, withRestTerm, withEnergy, gradient);
        }
        energy += elementEnergy;
        if (perElement) perElement[e] = elementEnergy;
        if (!sink) continue;
        for (int n = 0; n < count; ++n)
          for (int c = 0; c < 3; ++c) (*sink)(ids[n], c) += ge[n * 3 + c];
      }
      workerEnergy[worker] = energy;
    }
  });

  if (out) {
    for (unsigned w = 0; w < workers; ++w) *out += workerBuffers_[w];
  }
  double total = 0;
  for (double v : workerEnergy) total += v;
  return total;
}

}  // namespace sculpt
