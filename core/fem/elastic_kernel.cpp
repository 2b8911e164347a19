#include "fem/elastic_kernel.h"

#include <Eigen/LU>
#include <algorithm>
#include <array>

#include "fem/linear_kernel.h"
#include "fem/polar_rotation.h"
#include "fem/quadrature.h"
#include "fem/tricubic_kernel.h"
#include "subdiv/tricubic_patch.h"
#include "util/parallel_for.h"

namespace sculpt {
namespace {

// Weights of the parametric gradient at the element centre: dx/dxi_m = sum_n centre[m][n] x_n,
// node n = a*16 + b*4 + g.
struct TricubicTables {
  double centre[3][64];
  TricubicTables() {
    double Bc[4], Dc[4];
    cubicBSplineBasis(0.5, Bc, Dc);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int g = 0; g < 4; ++g) {
          centre[0][a * 16 + b * 4 + g] = Dc[a] * Bc[b] * Bc[g];
          centre[1][a * 16 + b * 4 + g] = Bc[a] * Dc[b] * Bc[g];
          centre[2][a * 16 + b * 4 + g] = Bc[a] * Bc[b] * Dc[g];
        }
  }
};
const TricubicTables& tables() {
  static const TricubicTables t;
  return t;
}

}  // namespace

ElasticKernel::ElasticKernel(const FemMesh& mesh)
    : mesh_(mesh), rotations_(mesh.numElements(), Eigen::Matrix3d::Identity()) {
  // Rest data of each tricubic element in one contiguous block (one memory stream, prefetched
  // as a whole; layout in tricubic_kernel.h). An element whose rest map is affine (the same
  // inverse Jacobian at all 64 Gauss points, to rounding: the regular interior of a lattice)
  // stores a single block of inverse Jacobians: a sixteenth of that data, which matters once
  // the model outgrows the caches.
  const uint32_t numTricubic = mesh.numTricubic();
  tricubicRestOffset_.resize(numTricubic + 1);
  tricubicAffine_.resize(numTricubic);
  tricubicAxisRows_.resize(numTricubic);
  tricubicRest_.clear();
  for (uint32_t e = 0; e < numTricubic; ++e) {
    const Eigen::Matrix3d* J = mesh.tricubicInverseJacobian.data() + size_t(e) * 64;
    const bool affine = affineInverseJacobians(J);
    tricubicRestOffset_[e] = tricubicRest_.size();
    tricubicAffine_[e] = affine;
    std::array<int8_t, 3> rows{-1, -1, -1};
    if (!affine || !axisAlignedRows(J[0], rows.data())) rows[0] = -1;
    tricubicAxisRows_[e] = rows;
    tricubicRest_.resize(tricubicRest_.size() + size_t(tricubicRestSize(affine)));
    packTricubicInverseJacobians(J, affine, tricubicRest_.data() + tricubicRestOffset_[e]);
  }
  tricubicRestOffset_[numTricubic] = tricubicRest_.size();
  // The kernel's own node numbering: nodes in the order the element loop first touches them,
  // so that consecutive elements gather from and scatter to nearby rows (the mesh numbers the
  // nodes of a level by kind: vertex, edge, face and cell points, far apart). The element node
  // lists are kept in that numbering.
  const uint32_t numNodes = mesh.numNodes();
  constexpr uint32_t kUnseen = ~0u;
  std::vector<uint32_t> kernelNode(numNodes, kUnseen);
  meshNode_.clear();
  meshNode_.reserve(numNodes);
  elementNodes_.clear();
  elementNodes_.reserve(size_t(numTricubic) * kTricubicNodes +
                        size_t(mesh.numLinear()) * kLinearNodes);
  auto number = [&](uint32_t node) {
    if (kernelNode[node] == kUnseen) {
      kernelNode[node] = uint32_t(meshNode_.size());
      meshNode_.push_back(node);
    }
    elementNodes_.push_back(kernelNode[node]);
  };
  for (const auto& nodes : mesh.tricubicNodes)
    for (uint32_t node : nodes) number(node);
  for (const auto& nodes : mesh.linearNodes)
    for (uint32_t node : nodes) number(node);
  for (uint32_t node = 0; node < numNodes; ++node)  // in no element: still a row
    if (kernelNode[node] == kUnseen) {
      kernelNode[node] = uint32_t(meshNode_.size());
      meshNode_.push_back(node);
    }
  restRows_.resize(numNodes, 4);
  for (uint32_t k = 0; k < numNodes; ++k) {
    restRows_.row(k).head<3>() = mesh.restNodes.row(meshNode_[k]);
    restRows_(k, 3) = 0.0;
  }
  linearShapeGradient_.resize(size_t(mesh.numLinear()) * 192);
  for (uint32_t l = 0; l < mesh.numLinear(); ++l)
    for (int q = 0; q < 8; ++q) {
      const LinearShapeGradient& dN = mesh.linearShapeGradient[size_t(l) * 8 + q];
      for (int a = 0; a < 8; ++a)
        for (int c = 0; c < 3; ++c)
          linearShapeGradient_[size_t(l) * 192 + (a * 3 + c) * 8 + q] = dN(a, c);
    }
  refreshMaterial();
}

void ElasticKernel::refreshMaterial() {
  const size_t count = size_t(mesh_.numTricubic()) * 64;
  for (uint32_t e = 0; e < mesh_.numTricubic(); ++e)
    packTricubicMaterial(mesh_.gaussVolume.data() + size_t(e) * 64,
                         mesh_.gaussLame.data() + size_t(e) * 64, tricubicAffine_[e],
                         tricubicRest_.data() + tricubicRestOffset_[e]);
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

void ElasticKernel::setModel(ElasticModel model, const InversionBarrier& barrier) {
  model_ = model;
  barrier_ = barrier;
  barrierState_.clear();
  barrierRecords_.clear();
  barrierElements_ = 0;
  barrierStale_ = false;
}

ElasticKernel::Jacobians ElasticKernel::jacobians(const Points& nodes) const {
  std::vector<BarrierRecord> records;
  run(nodes, Mode::Gradient, nullptr, false, nullptr, nullptr, &records, true);
  Jacobians result;
  for (const BarrierRecord& record : records) {
    size_t offset = 0;
    for (uint32_t e : record.elements) {
      const int points = e < mesh_.numTricubic() ? kTricubicGaussPoints : kLinearGaussPoints;
      const int lanes = e < mesh_.numTricubic() ? 4 : 8;  // the kernels' layout of A
      bool inverted = false;
      for (int q = 0; q < points; ++q) {
        const double* block = record.states.data() + offset + size_t(q / lanes) * 9 * size_t(lanes);
        Eigen::Matrix3d A;
        for (int rc = 0; rc < 9; ++rc) A(rc / 3, rc % 3) = block[rc * lanes + q % lanes];
        const double J = A.determinant();
        result.min = std::min(result.min, J);
        if (J <= 0) {
          ++result.invertedPoints;
          inverted = true;
        }
      }
      result.invertedElements += inverted ? 1 : 0;
      offset += size_t(points) * 9;
    }
  }
  return result;
}

uint32_t ElasticKernel::barrierElements() const {
  refreshBarrier();
  return barrierElements_;
}

void ElasticKernel::refreshBarrier() const {
  if (!barrierStale_) return;
  run(barrierNodes_, Mode::Gradient, nullptr, false, nullptr, nullptr, &barrierRecords_);
  keepBarrierRecords();
  barrierStale_ = false;
}

void ElasticKernel::keepBarrierRecords() const {
  barrierElements_ = 0;
  for (const BarrierRecord& record : barrierRecords_)
    barrierElements_ += uint32_t(record.elements.size());
  // Nothing in the barrier (most scenes, most of the time): the Hessian products skip it.
  if (barrierElements_ == 0) {
    barrierState_.clear();
    return;
  }
  barrierState_.assign(mesh_.numElements(), nullptr);
  for (const BarrierRecord& record : barrierRecords_) {
    size_t offset = 0;
    for (uint32_t e : record.elements) {
      barrierState_[e] = record.states.data() + offset;
      offset += 9 * size_t(e < mesh_.numTricubic() ? kTricubicGaussPoints : kLinearGaussPoints);
    }
  }
}

const uint32_t* ElasticKernel::elementNodes(uint32_t e) const {
  const uint32_t numTricubic = mesh_.numTricubic();
  return e < numTricubic
             ? elementNodes_.data() + size_t(e) * kTricubicNodes
             : elementNodes_.data() + size_t(numTricubic) * kTricubicNodes +
                   size_t(e - numTricubic) * kLinearNodes;
}

uint32_t ElasticKernel::gatherElement(uint32_t e, const NodeRows& x, double* ue) const {
  const int count = e < mesh_.numTricubic() ? kTricubicNodes : kLinearNodes;
  gatherNodeRows(x, elementNodes(e), count, ue);
  return uint32_t(count);
}

void ElasticKernel::loadSource(const Points& x, bool displacement) const {
  source_.resize(x.rows(), 4);
  for (Eigen::Index k = 0; k < x.rows(); ++k) {
    source_.row(k).head<3>() = x.row(meshNode_[size_t(k)]);
    source_(k, 3) = 0.0;
  }
  if (displacement) source_ -= restRows_;
}

Eigen::Matrix3d ElasticKernel::centreDeformationGradient(uint32_t e, const double* ue) const {
  // F = I + (du/dX) at the element centre, from the gathered displacements (the rest geometry
  // maps to I).
  Eigen::Matrix3d F;
  const uint32_t numTricubic = mesh_.numTricubic();
  if (e < numTricubic) {
    const TricubicTables& T = tables();
    using V4 = Eigen::Array4d;
    Eigen::Matrix3d G;  // G(c, m) = d u_c / d xi_m
    for (int c = 0; c < 3; ++c)
      for (int m = 0; m < 3; ++m) {
        V4 sum = V4::Zero();
        for (int n = 0; n < kTricubicNodes; n += 4)
          sum += Eigen::Map<const V4>(T.centre[m] + n) * Eigen::Map<const V4>(ue + c * 64 + n);
        G(c, m) = sum.sum();
      }
    F = G * mesh_.tricubicCentreInverseJacobian[e];
  } else {
    const LinearShapeGradient& dN = mesh_.linearCentreShapeGradient[e - numTricubic];
    for (int c = 0; c < 3; ++c)
      for (int m = 0; m < 3; ++m) {
        double sum = 0;
        for (int a = 0; a < kLinearNodes; ++a) sum += ue[c * kLinearNodes + a] * dN(a, m);
        F(c, m) = sum;
      }
  }
  F += Eigen::Matrix3d::Identity();
  return F;
}

void ElasticKernel::updateGroupRotations(uint32_t first, int count, const double (*ue)[192],
                                         Eigen::Matrix3d* newRotations) const {
  // Warm-started from the elements' last rotations, which change little between calls; four
  // elements at a time share the vector lanes.
  Eigen::Matrix3d F[4];
  for (int k = 0; k < count; ++k) F[k] = centreDeformationGradient(first + uint32_t(k), ue[k]);
  polarRotations(F, rotations_.data() + first, count, newRotations + first);
}

void ElasticKernel::updateRotations(const Points& nodes) {
  if (model_ == ElasticModel::Barrier) {
    barrierNodes_ = nodes;
    barrierStale_ = true;
  }
  loadSource(nodes, true);
  parallelChunks(mesh_.numElements(), 256, [&](uint32_t begin, uint32_t end, unsigned) {
    alignas(64) double ue[4][kTricubicNodes * 3];
    for (uint32_t first = begin; first < end; first += 4) {
      const int group = int(std::min<uint32_t>(4, end - first));
      for (int k = 0; k < group; ++k) gatherElement(first + uint32_t(k), source_, ue[k]);
      updateGroupRotations(first, group, ue, rotations_.data());
    }
  });
}

void ElasticKernel::updateRotationsAndAddGradient(const Points& nodes, Points& gradient) {
  if (model_ != ElasticModel::Barrier) {
    run(nodes, Mode::Gradient, &gradient, false, nullptr, rotations_.data());
    return;
  }
  run(nodes, Mode::Gradient, &gradient, false, nullptr, rotations_.data(), &barrierRecords_);
  keepBarrierRecords();
  barrierStale_ = false;
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
  refreshBarrier();
  run(dx, Mode::HessianProduct, &result, false);
}

double ElasticKernel::run(const Points& x, Mode mode, Points* out, bool withEnergy,
                          double* perElement, Eigen::Matrix3d* newRotations,
                          std::vector<BarrierRecord>* records, bool recordAll) const {
  const bool withRestTerm = mode == Mode::Gradient;  // x holds positions, not a direction
  const uint32_t numTricubic = mesh_.numTricubic();
  const uint32_t numElements = mesh_.numElements();
  const unsigned workers = std::min<unsigned>(workerCount(), std::max(1u, numElements / 32));
  if (out) workerBuffers_.resize(workers);
  std::vector<double> workerEnergy(workers, 0.0);
  if (records) {
    records->resize(workers);
    for (BarrierRecord& record : *records) {  // kept with their capacity: no reallocation
      record.elements.clear();
      record.states.clear();
    }
  }
  const InversionBarrier* barrier = model_ == ElasticModel::Barrier ? &barrier_ : nullptr;
  const bool hessianBarrier = mode == Mode::HessianProduct && !barrierState_.empty();
  // Records for the Hessian products keep only what they need (barrier_stress.h).
  const bool curvature = records && !recordAll && barrier && !barrier->exactHessian;
  // The kernels take displacements in gradient mode (x holds positions there).
  loadSource(x, withRestTerm);
  // Equal work per worker: a tricubic element costs about kTricubicCost linear ones.
  constexpr double kTricubicCost = 5.0;
  const double tricubicCost = kTricubicCost * numTricubic;
  const double totalCost = tricubicCost + (numElements - numTricubic);
  auto chunkStart = [&](unsigned k) {
    const double target = totalCost * k / workers;
    return target <= tricubicCost
               ? static_cast<uint32_t>(target / kTricubicCost)
               : std::min(numElements,
                          static_cast<uint32_t>(numTricubic + (target - tricubicCost)));
  };

  parallelChunks(workers, 1, [&](uint32_t firstWorker, uint32_t lastWorker, unsigned) {
    for (uint32_t worker = firstWorker; worker < lastWorker; ++worker) {
      NodeRows* sink = out ? &workerBuffers_[worker] : nullptr;
      if (sink) sink->setZero(mesh_.numNodes(), 4);
      double energy = 0;
      // Displacements (gradient) or the direction (Hessian) of four elements: their rotations
      // are found together.
      alignas(64) double ueGroup[4][64 * 3];
      alignas(64) double ge[64 * 3];
      alignas(64) double barrierRecord[9 * kTricubicGaussPoints];
      const uint32_t begin = chunkStart(worker);
      const uint32_t end = worker + 1 == workers ? numElements : chunkStart(worker + 1);
      for (uint32_t e = begin; e < end; ++e) {
        const bool tricubic = e < numTricubic;
        const double* ue = ueGroup[(e - begin) % 4];
        if ((e - begin) % 4 == 0) {
          const int group = int(std::min<uint32_t>(4, end - e));
          for (int k = 0; k < group; ++k) gatherElement(e + uint32_t(k), source_, ueGroup[k]);
          if (newRotations) updateGroupRotations(e, group, ueGroup, newRotations);
        }
        const uint32_t count = tricubic ? kTricubicNodes : kLinearNodes;
        const Eigen::Matrix3d& R = rotations_[e];
        double* gradient = sink ? ge : nullptr;
        double elementEnergy;
        BarrierArgs barrierArgs;
        barrierArgs.settings = barrier;
        if (records) barrierArgs.record = barrierRecord;
        if (barrier && hessianBarrier) barrierArgs.state = barrierState_[e];
        const double *volumeLambda, *volumeMu;  // the Gauss points' V lambda and V mu
        if (tricubic) {
          // The rest data (up to 5.6 KB per element) streams from memory once the model
          // outgrows the caches (K = 3): the kernel fetches the next element's while it
          // computes, a slice per stage so that the fetches do not queue up.
          const size_t restEnd = tricubicRestOffset_[e + 1];
          const TricubicPacked packed = tricubicPackedView(
              tricubicRest_.data() + tricubicRestOffset_[e], tricubicAffine_[e],
              tricubicRest_.data() + restEnd,
              int(e + 1 < numTricubic ? tricubicRestOffset_[e + 2] - restEnd : 0),
              tricubicAxisRows_[e][0] >= 0 ? tricubicAxisRows_[e].data() : nullptr);
          elementEnergy = tricubicElementKernel(ue, packed, R, withRestTerm, withEnergy, gradient,
                                                &barrierArgs);
          volumeLambda = packed.volumeLambda;
          volumeMu = packed.volumeMu;
        } else {
          const size_t l = e - numTricubic;
          const LinearPacked packed{linearShapeGradient_.data() + l * 192,
                                    linearVolumeLambda_.data() + l * 8,
                                    linearVolumeMu_.data() + l * 8};
          elementEnergy = linearElementKernel(ue, packed, R, withRestTerm, withEnergy, gradient,
                                              &barrierArgs);
          volumeLambda = packed.volumeLambda;
          volumeMu = packed.volumeMu;
        }
        energy += elementEnergy;
        if (perElement) perElement[e] = elementEnergy;
        if (barrierArgs.record && (barrierArgs.active || recordAll)) {
          if (curvature)
            recordCurvature(barrierRecord, tricubic ? kTricubicGaussPoints : kLinearGaussPoints,
                            tricubic ? 4 : 8, volumeLambda, volumeMu, *barrier);
          BarrierRecord& record = (*records)[worker];
          record.elements.push_back(e);
          record.states.insert(
              record.states.end(), barrierRecord,
              barrierRecord + 9 * (tricubic ? kTricubicGaussPoints : kLinearGaussPoints));
        }
        if (!sink) continue;
        scatterAddNodeRows(ge, elementNodes(e), int(count), *sink);
      }
      workerEnergy[worker] = energy;
    }
  });

  if (out) {
    for (uint32_t k = 0; k < mesh_.numNodes(); ++k) {
      Eigen::RowVector4d sum = workerBuffers_[0].row(k);
      for (unsigned w = 1; w < workers; ++w) sum += workerBuffers_[w].row(k);
      out->row(meshNode_[k]) += sum.head<3>();
    }
  }
  double total = 0;
  for (double v : workerEnergy) total += v;
  return total;
}

}  // namespace sculpt
