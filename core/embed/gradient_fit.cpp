#include "embed/gradient_fit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>
#include <utility>

#include "util/compressed_rows.h"
#include "util/parallel_for.h"

namespace sculpt {
namespace {

using FitMatrix = Eigen::Matrix<double, 9, 9>;
using Monomials = Eigen::Matrix<double, 9, 1>;

/// Nodes sharing a cell with each node (itself excluded), sorted.
CompressedRows<uint32_t> nodeNeighbours(const VolumeMesh& mesh) {
  const CompressedRows<uint32_t> nodeCells = invertIncidence(mesh.cells, mesh.numNodes());
  CompressedRows<uint32_t> neighbours;
  std::vector<uint32_t> row;
  for (uint32_t node = 0; node < mesh.numNodes(); ++node) {
    row.clear();
    for (uint32_t cell : nodeCells.row(node))
      for (uint32_t other : mesh.cells.row(cell))
        if (other != node) row.push_back(other);
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    neighbours.values.insert(neighbours.values.end(), row.begin(), row.end());
    neighbours.closeRow();
  }
  return neighbours;
}

Monomials monomials(const Eigen::Vector3d& d) {
  Monomials m;
  m << d.x(), d.y(), d.z(), d.x() * d.x(), d.y() * d.y(), d.z() * d.z(), d.x() * d.y(),
      d.x() * d.z(), d.y() * d.z();
  return m;
}

/// One node's stencil row: (neighbour, G_ij) terms sorted by neighbour.
using StencilRow = std::vector<std::pair<uint32_t, Eigen::Vector3d>>;

/// The fit over `ring` (node i excluded): its terms, node i's included, and the condition number
/// of its normal matrix (infinite where the ring cannot determine a quadratic).
double fitRow(const VolumeMesh& rest, uint32_t node, const std::vector<uint32_t>& ring,
              StencilRow& row) {
  constexpr double kUnfit = std::numeric_limits<double>::infinity();
  if (ring.size() + 1 < kMinFitNodes) return kUnfit;
  const Eigen::Vector3d origin = rest.positions.row(node).transpose();
  double radius = 0.0;
  for (uint32_t j : ring)
    radius = std::max(radius, (rest.positions.row(j).transpose() - origin).norm());
  if (!(radius > 0.0)) return kUnfit;
  // Scaled to the ring's radius, so the condition number measures the ring's shape, not its size.
  FitMatrix normal = FitMatrix::Zero();
  for (uint32_t j : ring) {
    const Monomials m = monomials((rest.positions.row(j).transpose() - origin) / radius);
    normal.noalias() += m * m.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<FitMatrix> eigen(normal);
  if (eigen.info() != Eigen::Success) return kUnfit;
  const double smallest = eigen.eigenvalues()(0), largest = eigen.eigenvalues()(8);
  if (!(smallest > 0.0) || !(largest <= kMaxFitCondition * smallest)) return kUnfit;
  // The gradient's rows of normal^-1: P = (V diag(1/lambda) V^T)[0..2, :].
  const Eigen::Matrix<double, 3, 9> gradientRows = eigen.eigenvectors().topRows<3>() *
                                                   eigen.eigenvalues().cwiseInverse().asDiagonal() *
                                                   eigen.eigenvectors().transpose();
  row.clear();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (uint32_t j : ring) {
    const Eigen::Vector3d g =
        gradientRows * monomials((rest.positions.row(j).transpose() - origin) / radius) / radius;
    row.emplace_back(j, g);
    sum += g;
  }
  row.emplace_back(node, -sum);  // x_j - x_i: the node itself takes minus the others' sum
  std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return largest / smallest;
}

}  // namespace

NodeGradientStencil quadraticFitStencil(const VolumeMesh& rest, const NodeGradientStencil& fallback,
                                        GradientFitReport* report) {
  const uint32_t numNodes = rest.numNodes();
  const CompressedRows<uint32_t> neighbours = nodeNeighbours(rest);

  // Rows per node, made in parallel; each worker keeps its own ring marks.
  std::vector<StencilRow> rows(numNodes);
  std::vector<uint8_t> ringOf(numNodes, 0);  // 0: fallback
  parallelChunks(numNodes, 512, [&](uint32_t begin, uint32_t end, unsigned) {
    std::vector<uint32_t> mark(numNodes, UINT32_MAX);
    std::vector<uint32_t> ring, frontier, next;
    StencilRow candidate;
    for (uint32_t node = begin; node < end; ++node) {
      ring.clear();
      frontier.assign(1, node);
      mark[node] = node;
      double best = std::numeric_limits<double>::infinity();
      for (uint32_t k = 1; k <= kMaxFitRing && !frontier.empty(); ++k) {
        next.clear();
        for (uint32_t f : frontier)
          for (uint32_t j : neighbours.row(f))
            if (mark[j] != node) {
              mark[j] = node;
              next.push_back(j);
            }
        ring.insert(ring.end(), next.begin(), next.end());
        std::swap(frontier, next);
        const double condition = fitRow(rest, node, ring, candidate);
        if (condition < best) {
          best = condition;
          std::swap(rows[node], candidate);
          ringOf[node] = static_cast<uint8_t>(k);
        }
        if (best <= kGoodFitCondition) break;
      }
    }
  });

  NodeGradientStencil stencil;
  stencil.offsets.reserve(numNodes + 1);
  GradientFitReport counts;
  for (uint32_t node = 0; node < numNodes; ++node) {
    if (ringOf[node] == 0) {
      ++counts.fallbacks;
      if (node < fallback.numNodes())
        for (uint32_t t = fallback.offsets[node]; t < fallback.offsets[node + 1]; ++t) {
          stencil.nodes.push_back(fallback.nodes[t]);
          stencil.g.insert(stencil.g.end(), fallback.g.begin() + 3 * t,
                           fallback.g.begin() + 3 * t + 3);
        }
    } else {
      ++counts.ringCounts[ringOf[node]];
      for (const auto& [j, g] : rows[node]) {
        stencil.nodes.push_back(j);
        stencil.g.insert(stencil.g.end(), {g[0], g[1], g[2]});
      }
    }
    stencil.offsets.push_back(static_cast<uint32_t>(stencil.nodes.size()));
  }
  if (report) *report = counts;
  return stencil;
}

}  // namespace sculpt
