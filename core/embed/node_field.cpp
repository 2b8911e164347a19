#include "embed/node_field.h"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

#include "embed/cell_coordinates.h"

namespace sculpt {
namespace {

/// integral over `cell` of N_a dV for each of its nodes a. A tetrahedron's N_a are its
/// barycentric weights: V / 4 each. A hexahedron's N_a det J has degree at most 3 along each
/// local axis (N_a linear, det J quadratic), so the 2 x 2 x 2 Gauss rule is exact.
int cornerVolumes(const VolumeMesh& mesh, uint32_t cell, double volumes[8]) {
  if (mesh.isTetrahedron(cell)) {
    const double quarter = std::abs(tetrahedronSignedVolume(mesh, cell)) / 4.0;
    for (int a = 0; a < 4; ++a) volumes[a] = quarter;
    return 4;
  }
  const double offset = 0.5 / std::sqrt(3.0);
  const double gauss[2] = {0.5 - offset, 0.5 + offset};
  for (int a = 0; a < 8; ++a) volumes[a] = 0.0;
  for (const double s : gauss)
    for (const double t : gauss)
      for (const double u : gauss) {
        const Eigen::Vector3d xi(s, t, u);
        const double weight = cellJacobian(mesh, cell, xi).determinant() / 8.0;
        double N[8];
        cellNodeWeights(false, xi, N);
        for (int a = 0; a < 8; ++a) volumes[a] += weight * N[a];
      }
  for (int a = 0; a < 8; ++a) volumes[a] = std::abs(volumes[a]);
  return 8;
}

}  // namespace

CompressedRows<NodeFieldWeight> nodeFieldWeights(const VolumeMesh& mesh) {
  const CompressedRows<uint32_t> incident = invertIncidence(mesh.cells, mesh.numNodes());
  // Each cell's corner volumes, in its row order.
  std::vector<double> corner(mesh.cells.values.size());
  for (uint32_t c = 0; c < mesh.numCells(); ++c)
    cornerVolumes(mesh, c, corner.data() + mesh.cells.offsets[c]);

  CompressedRows<NodeFieldWeight> weights;
  weights.offsets = incident.offsets;
  weights.values.resize(incident.values.size());
  for (uint32_t i = 0; i < mesh.numNodes(); ++i) {
    const auto cells = incident.row(i);
    NodeFieldWeight* row = weights.values.data() + incident.offsets[i];
    double total = 0.0;
    for (size_t k = 0; k < cells.size(); ++k) {
      const uint32_t c = cells[k];
      const auto nodes = mesh.cells.row(c);
      double share = 0.0;
      for (size_t a = 0; a < nodes.size(); ++a)
        if (nodes[a] == i) share += corner[mesh.cells.offsets[c] + a];
      row[k] = {c, share};
      total += share;
    }
    // Degenerate cells only (no volume at the node): equal weights keep the mean defined.
    for (size_t k = 0; k < cells.size(); ++k)
      row[k].weight = total > 0.0 ? row[k].weight / total : 1.0 / static_cast<double>(cells.size());
  }
  return weights;
}

void nodeFieldFromCells(const CompressedRows<NodeFieldWeight>& weights,
                        std::span<const float> cellValues, std::vector<float>& nodeValues) {
  nodeValues.resize(weights.numRows());
  for (uint32_t i = 0; i < weights.numRows(); ++i) {
    double value = 0.0;
    for (const NodeFieldWeight& w : weights.row(i)) {
      if (w.cell >= cellValues.size())
        throw std::invalid_argument("nodeFieldFromCells: cell " + std::to_string(w.cell) + " of " +
                                    std::to_string(cellValues.size()) + " cell values");
      value += w.weight * static_cast<double>(cellValues[w.cell]);
    }
    nodeValues[i] = static_cast<float>(value);
  }
}

}  // namespace sculpt
