#include "sim/material_point.h"

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

#include "fem/trilinear_shape.h"
#include "subdiv/tricubic_patch.h"

namespace sculpt {
namespace {

void checkElement(const FemMesh& mesh, uint32_t element) {
  if (element >= mesh.numElements())
    throw std::invalid_argument("material point element " + std::to_string(element) +
                                " is out of range (the mesh has " +
                                std::to_string(mesh.numElements()) + " elements)");
}

}  // namespace

std::vector<std::pair<uint32_t, double>> nodeWeights(const FemMesh& mesh,
                                                     const MaterialPoint& point) {
  checkElement(mesh, point.element);
  std::vector<std::pair<uint32_t, double>> weights;
  if (point.element < mesh.numTricubic()) {
    double bu[4], bv[4], bw[4];
    cubicBSplineBasis(point.local[0], bu);
    cubicBSplineBasis(point.local[1], bv);
    cubicBSplineBasis(point.local[2], bw);
    const auto& ids = mesh.tricubicNodes[point.element];
    weights.reserve(kTricubicNodes);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int g = 0; g < 4; ++g)
          weights.emplace_back(ids[size_t(a * 16 + b * 4 + g)], bu[a] * bv[b] * bw[g]);
    return weights;
  }
  const auto& ids = mesh.linearNodes[point.element - mesh.numTricubic()];
  double N[8], dN[8][3];
  trilinearShape(point.local, N, dN);
  for (int a = 0; a < kLinearNodes; ++a) {
    const uint32_t id = ids[size_t(a)];
    auto it = std::find_if(weights.begin(), weights.end(),
                           [id](const auto& entry) { return entry.first == id; });
    if (it != weights.end()) it->second += N[a];
    else weights.emplace_back(id, N[a]);
  }
  return weights;
}

std::vector<std::pair<uint32_t, double>> controlWeights(const FemMesh& mesh,
                                                        const MaterialPoint& point) {
  std::map<uint32_t, double> merged;
  const StencilTable& A = mesh.nodeStencils;
  for (const auto& [node, weight] : nodeWeights(mesh, point)) {
    for (uint32_t k = A.offsets()[node]; k < A.offsets()[node + 1]; ++k)
      merged[A.indices()[k]] += weight * A.weights()[k];
  }
  return {merged.begin(), merged.end()};
}

Eigen::Vector3d materialPointPosition(const FemMesh& mesh, const Points& nodes,
                                      const MaterialPoint& point) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (const auto& [node, weight] : nodeWeights(mesh, point))
    x += weight * nodes.row(node).transpose();
  return x;
}

Eigen::Vector3d elementMap(const FemMesh& mesh, const Points& nodes, uint32_t element,
                           const Eigen::Vector3d& local, Eigen::Matrix3d* jacobian) {
  checkElement(mesh, element);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  if (element < mesh.numTricubic()) {
    double bu[4], bv[4], bw[4], du[4], dv[4], dw[4];
    cubicBSplineBasis(local[0], bu, du);
    cubicBSplineBasis(local[1], bv, dv);
    cubicBSplineBasis(local[2], bw, dw);
    const auto& ids = mesh.tricubicNodes[element];
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int g = 0; g < 4; ++g) {
          const Eigen::Vector3d X = nodes.row(ids[size_t(a * 16 + b * 4 + g)]).transpose();
          x += bu[a] * bv[b] * bw[g] * X;
          J.col(0) += du[a] * bv[b] * bw[g] * X;
          J.col(1) += bu[a] * dv[b] * bw[g] * X;
          J.col(2) += bu[a] * bv[b] * dw[g] * X;
        }
  } else {
    const auto& ids = mesh.linearNodes[element - mesh.numTricubic()];
    double N[8], dN[8][3];
    trilinearShape(local, N, dN);
    for (int a = 0; a < kLinearNodes; ++a) {
      const Eigen::Vector3d X = nodes.row(ids[size_t(a)]).transpose();
      x += N[a] * X;
      for (int d = 0; d < 3; ++d) J.col(d) += dN[a][d] * X;
    }
  }
  if (jacobian) *jacobian = J;
  return x;
}

MaterialPointLocator::MaterialPointLocator(const FemMesh& mesh) : mesh_(mesh) {
  const uint32_t numElements = mesh.numElements();
  if (numElements == 0) return;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  boxes_.resize(numElements);
  for (uint32_t e = 0; e < numElements; ++e) {
    Box box{lo, hi};
    auto add = [&](uint32_t node) {
      const Eigen::Vector3d X = mesh.restNodes.row(node).transpose();
      box.lo = box.lo.cwiseMin(X);
      box.hi = box.hi.cwiseMax(X);
    };
    for (uint32_t node : mesh.elementNodes(e)) add(node);
    boxes_[e] = box;
  }
  Eigen::Vector3d allLo = boxes_[0].lo, allHi = boxes_[0].hi;
  for (const Box& box : boxes_) {
    allLo = allLo.cwiseMin(box.lo);
    allHi = allHi.cwiseMax(box.hi);
  }
  const double scale = std::max((allHi - allLo).norm(), std::numeric_limits<double>::min());
  insideTolerance_ = 1e-10 * scale;
  const double pad = 1e-9 * scale;
  for (Box& box : boxes_) {
    box.lo.array() -= pad;
    box.hi.array() += pad;
  }
  allLo.array() -= pad;
  allHi.array() += pad;

  // Uniform grid with about one element per grid cell.
  const int perAxis =
      std::clamp(static_cast<int>(std::ceil(std::cbrt(static_cast<double>(numElements)))), 1, 128);
  gridLo_ = allLo;
  gridSize_ = Eigen::Vector3i::Constant(perAxis);
  gridCell_ = ((allHi - allLo) / static_cast<double>(perAxis)).cwiseMax(pad);
  auto cellRange = [&](const Box& box, Eigen::Vector3i& first, Eigen::Vector3i& last) {
    for (int d = 0; d < 3; ++d) {
      first[d] = std::clamp(static_cast<int>(std::floor((box.lo[d] - gridLo_[d]) / gridCell_[d])),
                            0, perAxis - 1);
      last[d] = std::clamp(static_cast<int>(std::floor((box.hi[d] - gridLo_[d]) / gridCell_[d])),
                           0, perAxis - 1);
    }
  };
  const size_t numCells = size_t(perAxis) * size_t(perAxis) * size_t(perAxis);
  std::vector<uint32_t> counts(numCells + 1, 0);
  auto forEachCell = [&](const Box& box, auto&& body) {
    Eigen::Vector3i first, last;
    cellRange(box, first, last);
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i)
          body(size_t(i) + size_t(perAxis) * (size_t(j) + size_t(perAxis) * size_t(k)));
  };
  for (const Box& box : boxes_) forEachCell(box, [&](size_t cell) { ++counts[cell + 1]; });
  for (size_t c = 0; c < numCells; ++c) counts[c + 1] += counts[c];
  gridBegin_ = counts;
  gridElements_.resize(gridBegin_.back());
  std::vector<uint32_t> cursor(counts.begin(), counts.end() - 1);
  for (uint32_t e = 0; e < numElements; ++e)
    forEachCell(boxes_[e], [&](size_t cell) { gridElements_[cursor[cell]++] = e; });
}

double MaterialPointLocator::boxDistanceSquared(uint32_t e, const Eigen::Vector3d& X) const {
  const Box& box = boxes_[e];
  const Eigen::Vector3d outside =
      (box.lo - X).cwiseMax(X - box.hi).cwiseMax(Eigen::Vector3d::Zero());
  return outside.squaredNorm();
}

double MaterialPointLocator::closestLocal(uint32_t e, const Eigen::Vector3d& X,
                                          Eigen::Vector3d& local) const {
  // Gauss-Newton on |x(xi) - X|^2 over the box [0,1]^3: variables at a bound whose gradient
  // pushes outward are held; the step is the least-squares solution of J_F d = -r on the free
  // ones, projected onto the box and halved until the distance decreases. Inside an element this
  // is Newton's method on x(xi) = X and converges quadratically.
  Eigen::Vector3d xi(0.5, 0.5, 0.5);
  Eigen::Matrix3d J;
  Eigen::Vector3d r = elementMap(mesh_, mesh_.restNodes, e, xi, &J) - X;
  double f = r.squaredNorm();
  auto tryStep = [&](const Eigen::Vector3d& direction, double t0) {
    double t = t0;
    for (int halving = 0; halving < 40; ++halving, t *= 0.5) {
      const Eigen::Vector3d candidate = (xi + t * direction).cwiseMax(0.0).cwiseMin(1.0);
      Eigen::Matrix3d Jc;
      const Eigen::Vector3d rc = elementMap(mesh_, mesh_.restNodes, e, candidate, &Jc) - X;
      const double fc = rc.squaredNorm();
      if (fc < f) {
        const double moved = (candidate - xi).norm();
        xi = candidate;
        r = rc;
        J = Jc;
        f = fc;
        return moved;
      }
    }
    return -1.0;
  };
  for (int iteration = 0; iteration < 100 && f > 0; ++iteration) {
    const Eigen::Vector3d g = J.transpose() * r;
    int free[3], numFree = 0;
    for (int d = 0; d < 3; ++d) {
      const bool held = (xi[d] <= 0.0 && g[d] > 0.0) || (xi[d] >= 1.0 && g[d] < 0.0);
      if (!held) free[numFree++] = d;
    }
    if (numFree == 0) break;
    Eigen::MatrixXd JF(3, numFree);
    for (int k = 0; k < numFree; ++k) JF.col(k) = J.col(free[k]);
    const Eigen::VectorXd dF = JF.completeOrthogonalDecomposition().solve(-r);
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    for (int k = 0; k < numFree; ++k) direction[free[k]] = dF[k];
    double moved = direction.allFinite() ? tryStep(direction, 1.0) : -1.0;
    if (moved < 0) {
      // Fall back to a projected steepest-descent (Cauchy) step.
      Eigen::Vector3d descent = Eigen::Vector3d::Zero();
      for (int k = 0; k < numFree; ++k) descent[free[k]] = -g[free[k]];
      const double curvature = (J * descent).squaredNorm();
      if (!(curvature > 0)) break;
      moved = tryStep(descent, descent.squaredNorm() / curvature);
    }
    if (moved < 0 || moved < 1e-15) break;
  }
  local = xi;
  return f;
}

bool MaterialPointLocator::invert(uint32_t e, const Eigen::Vector3d& X,
                                  Eigen::Vector3d& local) const {
  // Plain Newton on x(xi) = X from the element centre; gives up when xi leaves the element by a
  // wide margin or the iteration stalls (the bounded search in closestLocal handles the rest).
  Eigen::Vector3d xi(0.5, 0.5, 0.5);
  const double tolerance2 = insideTolerance_ * insideTolerance_;
  for (int iteration = 0; iteration < 30; ++iteration) {
    Eigen::Matrix3d J;
    const Eigen::Vector3d r = elementMap(mesh_, mesh_.restNodes, e, xi, &J) - X;
    if (r.squaredNorm() <= 1e-12 * tolerance2) break;
    const Eigen::Vector3d step = J.partialPivLu().solve(-r);
    if (!step.allFinite()) return false;
    xi += step;
    if ((xi.array() < -0.5).any() || (xi.array() > 1.5).any()) return false;
    if (step.squaredNorm() < 1e-30) break;
  }
  const double slack = 1e-12;
  if ((xi.array() < -slack).any() || (xi.array() > 1 + slack).any()) return false;
  xi = xi.cwiseMax(0.0).cwiseMin(1.0);
  local = xi;
  return (elementMap(mesh_, mesh_.restNodes, e, xi) - X).squaredNorm() <= tolerance2;
}

std::optional<MaterialPoint> MaterialPointLocator::locate(const Eigen::Vector3d& X) const {
  if (boxes_.empty() || !X.allFinite()) return std::nullopt;

  // Elements whose box contains X, from the grid cell of X, nearest box centre first.
  bool inGrid = true;
  size_t cell = 0, stride = 1;
  for (int d = 0; d < 3; ++d) {
    const double t = std::floor((X[d] - gridLo_[d]) / gridCell_[d]);
    if (!(t >= 0) || t > gridSize_[d]) {
      inGrid = false;
      break;
    }
    cell += stride * std::min(static_cast<size_t>(t), size_t(gridSize_[d] - 1));
    stride *= size_t(gridSize_[d]);
  }
  if (inGrid) {
    std::vector<std::pair<double, uint32_t>> candidates;
    for (uint32_t k = gridBegin_[cell]; k < gridBegin_[cell + 1]; ++k) {
      const uint32_t e = gridElements_[k];
      if (boxDistanceSquared(e, X) > 0) continue;
      const Box& box = boxes_[e];
      candidates.emplace_back((0.5 * (box.lo + box.hi) - X).squaredNorm(), e);
    }
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [centreDistance, e] : candidates) {
      MaterialPoint point{e, {}};
      if (invert(e, X, point.local)) return point;
    }
  }

  // Nearest element: boxes in order of distance, until no box can beat the best point found.
  const double inside2 = insideTolerance_ * insideTolerance_;
  double best = std::numeric_limits<double>::infinity();
  MaterialPoint bestPoint;
  std::vector<std::pair<double, uint32_t>> order;
  order.reserve(boxes_.size());
  for (uint32_t e = 0; e < static_cast<uint32_t>(boxes_.size()); ++e)
    order.emplace_back(boxDistanceSquared(e, X), e);
  std::sort(order.begin(), order.end());
  for (const auto& [boxDistance, e] : order) {
    if (boxDistance >= best) break;
    Eigen::Vector3d local;
    const double d2 = closestLocal(e, X, local);
    if (d2 < best) {
      best = d2;
      bestPoint = {e, local};
      if (d2 <= inside2) break;
    }
  }
  return bestPoint;
}

std::optional<MaterialPoint> locateMaterialPoint(const FemMesh& mesh,
                                                 const Eigen::Vector3d& restPosition) {
  if (mesh.numElements() == 0 || !restPosition.allFinite()) return std::nullopt;
  return MaterialPointLocator(mesh).locate(restPosition);
}

}  // namespace sculpt
