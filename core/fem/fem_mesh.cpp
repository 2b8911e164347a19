#include "fem/fem_mesh.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <map>

#include "fem/quadrature.h"
#include "fem/trilinear_shape.h"
#include "mesh/hexahedron.h"
#include "subdiv/regularity.h"
#include "subdiv/tricubic_patch.h"

namespace sculpt {

const char* elementTypeName(ElementType type) {
  switch (type) {
    case ElementType::Tricubic: return "tricubic";
    case ElementType::Trilinear: return "trilinear";
    case ElementType::Pyramid: return "pyramid";
  }
  return "unknown";
}

uint32_t FemMesh::gaussBegin(uint32_t e) const {
  const uint32_t t = numTricubic();
  return e < t ? e * kTricubicGaussPoints : t * kTricubicGaussPoints + (e - t) * kLinearGaussPoints;
}

uint32_t FemMesh::gaussCount(uint32_t e) const {
  return e < numTricubic() ? kTricubicGaussPoints : kLinearGaussPoints;
}

ElementCounts FemMesh::counts() const {
  ElementCounts c;
  for (ElementType t : elementType) {
    if (t == ElementType::Tricubic) ++c.tricubic;
    else if (t == ElementType::Trilinear) ++c.trilinear;
    else ++c.pyramid;
  }
  return c;
}

double FemMesh::restVolume() const {
  double v = 0;
  for (double g : gaussVolume) v += g;
  return v;
}

namespace {

// Rows of `stencils` followed by one row per centre: the mean of the listed rows.
StencilTable appendCentreRows(const StencilTable& stencils,
                              const std::vector<std::vector<uint32_t>>& centres) {
  std::vector<uint32_t> offsets = stencils.offsets();
  std::vector<uint32_t> indices = stencils.indices();
  std::vector<double> weights = stencils.weights();
  std::map<uint32_t, double> row;
  for (const auto& members : centres) {
    row.clear();
    const double share = 1.0 / static_cast<double>(members.size());
    for (uint32_t node : members) {
      for (uint32_t k = stencils.offsets()[node]; k < stencils.offsets()[node + 1]; ++k)
        row[stencils.indices()[k]] += share * stencils.weights()[k];
    }
    for (const auto& [column, weight] : row) {
      indices.push_back(column);
      weights.push_back(weight);
    }
    offsets.push_back(static_cast<uint32_t>(indices.size()));
  }
  return StencilTable(stencils.numColumns(), std::move(offsets), std::move(indices),
                      std::move(weights));
}

// One row per centre over the lattice nodes: the mean of its members.
StencilTable centreRows(uint32_t numLatticeNodes,
                        const std::vector<std::vector<uint32_t>>& centres) {
  std::vector<uint32_t> offsets{0}, indices;
  std::vector<double> weights;
  for (const auto& members : centres) {
    for (uint32_t node : members) {
      indices.push_back(node);
      weights.push_back(1.0 / static_cast<double>(members.size()));
    }
    offsets.push_back(static_cast<uint32_t>(indices.size()));
  }
  return StencilTable(numLatticeNodes, std::move(offsets), std::move(indices), std::move(weights));
}

struct LinearElementPlan {
  std::array<uint32_t, kLinearNodes> nodes;
  ElementType type;
  uint32_t cell;
};

}  // namespace

std::optional<FemMesh> buildFemMesh(const CellComplex& cells, const Topology& topology,
                                    const StencilTable& stencils, const FemMeshOptions& options,
                                    std::string* error) {
  auto fail = [&](std::string message) -> std::optional<FemMesh> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  if (const std::string problem = materialProblem(options.material); !problem.empty())
    return fail("invalid material: " + problem);
  if (stencils.numRows() != cells.numVertices())
    return fail("the stencil table has " + std::to_string(stencils.numRows()) +
                " rows for " + std::to_string(cells.numVertices()) + " vertices");

  FemMesh mesh;
  mesh.numLatticeNodes = cells.numVertices();
  const std::vector<CellRegularity> regularity = classifyCells(topology);

  // Plan the elements: tricubic blocks, then trilinear hexahedra and pyramids in cell order.
  std::vector<std::pair<uint32_t, ControlBlock>> tricubic;
  std::vector<LinearElementPlan> linear;
  std::vector<std::vector<uint32_t>> centres;
  for (uint32_t c = 0; c < topology.numCells(); ++c) {
    if (options.allowTricubic && regularity[c] == CellRegularity::Regular) {
      if (auto block = regularControlBlock(topology, c)) {
        tricubic.emplace_back(c, *block);
        continue;
      }
    }
    if (auto hex = vtkHexahedronOrder(topology, c)) {
      linear.push_back({*hex, ElementType::Trilinear, c});
      continue;
    }
    // Irregular cell: a virtual centre node and one pyramid per face.
    const uint32_t centre = mesh.numLatticeNodes + static_cast<uint32_t>(centres.size());
    const auto members = topology.cellVertices.row(c);
    centres.emplace_back(members.begin(), members.end());
    for (uint32_t slot = 0; slot < topology.cellFaces.rowSize(c); ++slot) {
      const std::vector<uint32_t> loop = topology.outwardLoop(c, slot);
      if (loop.size() > 4)
        return fail("cell " + std::to_string(c) + " has a face with " +
                    std::to_string(loop.size()) +
                    " vertices; pyramid elements need triangles or quadrilaterals (subdivide "
                    "at least once)");
      // The reversed outward loop is a base whose normal points into the cell, towards the
      // centre; a triangle repeats its last vertex.
      const std::array<uint32_t, 4> base =
          loop.size() == 4 ? std::array<uint32_t, 4>{loop[0], loop[3], loop[2], loop[1]}
                           : std::array<uint32_t, 4>{loop[0], loop[2], loop[1], loop[1]};
      linear.push_back({{base[0], base[1], base[2], base[3], centre, centre, centre, centre},
                        ElementType::Pyramid,
                        c});
    }
  }

  mesh.nodeStencils = centres.empty() ? stencils : appendCentreRows(stencils, centres);
  mesh.centreStencils = centreRows(mesh.numLatticeNodes, centres);
  mesh.restNodes.resize(mesh.numNodes(), 3);
  mesh.restNodes.topRows(mesh.numLatticeNodes) = cells.positions;
  for (size_t k = 0; k < centres.size(); ++k) {
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (uint32_t v : centres[k]) sum += cells.positions.row(v);
    mesh.restNodes.row(mesh.numLatticeNodes + static_cast<Eigen::Index>(k)) =
        sum / static_cast<double>(centres[k].size());
  }

  for (const auto& [cell, block] : tricubic) {
    mesh.elementType.push_back(ElementType::Tricubic);
    mesh.elementCell.push_back(cell);
    mesh.tricubicNodes.push_back(block);
  }
  for (const LinearElementPlan& plan : linear) {
    mesh.elementType.push_back(plan.type);
    mesh.elementCell.push_back(plan.cell);
    mesh.linearNodes.push_back(plan.nodes);
  }

  // Rest data at the Gauss points.
  const QuadratureRule gauss4 = gaussLegendre(4);
  const QuadratureRule gauss2 = gaussLegendre(2);
  const QuadratureRule collapsed = collapsedPyramidRule();
  double B[4][4], D[4][4];  // B[i][a] = B_a(u_i)
  for (int i = 0; i < 4; ++i) cubicBSplineBasis(gauss4.points[i], B[i], D[i]);
  double Bc[4], Dc[4];
  cubicBSplineBasis(0.5, Bc, Dc);

  // Reserved: grown by copies, these (block10 at level 1: 27 MB of inverse Jacobians) cost the
  // build page faults and copying.
  const size_t gaussPoints =
      size_t(mesh.numTricubic()) * 64 + size_t(mesh.numLinear()) * kLinearGaussPoints;
  mesh.tricubicCentreInverseJacobian.reserve(mesh.numTricubic());
  mesh.tricubicInverseJacobian.reserve(size_t(mesh.numTricubic()) * 64);
  mesh.gaussVolume.reserve(gaussPoints);
  mesh.gaussRestPosition.reserve(gaussPoints);

  auto badJacobian = [&](uint32_t e, double det) {
    return "element " + std::to_string(e) + " (" + elementTypeName(mesh.elementType[e]) +
           ", cell " + std::to_string(mesh.elementCell[e]) +
           ") is inverted or degenerate at rest (det J = " + std::to_string(det) + ")";
  };

  for (uint32_t t = 0; t < mesh.numTricubic(); ++t) {
    const auto& nodes = mesh.tricubicNodes[t];
    auto jacobianAt = [&](const double* bu, const double* du, const double* bv, const double* dv,
                          const double* bw, const double* dw, Eigen::Vector3d& position) {
      Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
      position.setZero();
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          for (int g = 0; g < 4; ++g) {
            const Eigen::Vector3d X = mesh.restNodes.row(nodes[a * 16 + b * 4 + g]).transpose();
            position += bu[a] * bv[b] * bw[g] * X;
            J.col(0) += du[a] * bv[b] * bw[g] * X;
            J.col(1) += bu[a] * dv[b] * bw[g] * X;
            J.col(2) += bu[a] * bv[b] * dw[g] * X;
          }
      return J;
    };
    Eigen::Vector3d centre;
    const Eigen::Matrix3d Jc = jacobianAt(Bc, Dc, Bc, Dc, Bc, Dc, centre);
    if (!(Jc.determinant() > 0)) return fail(badJacobian(t, Jc.determinant()));
    mesh.tricubicCentreInverseJacobian.push_back(Jc.inverse());
    // At the 4x4x4 Gauss points by sum factorisation, one axis at a time (g, then b, then a):
    // about a tenth of the work of summing all 64 nodes at each point, which took half of a
    // default scene's element build.
    Eigen::Vector3d w0[4][4][4], w1[4][4][4];  // [a][b][k]: over g with B_g(w_k), B'_g(w_k)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        Eigen::Vector3d X[4];
        for (int g = 0; g < 4; ++g)
          X[g] = mesh.restNodes.row(nodes[a * 16 + b * 4 + g]).transpose();
        for (int k = 0; k < 4; ++k) {
          w0[a][b][k] = B[k][0] * X[0] + B[k][1] * X[1] + B[k][2] * X[2] + B[k][3] * X[3];
          w1[a][b][k] = D[k][0] * X[0] + D[k][1] * X[1] + D[k][2] * X[2] + D[k][3] * X[3];
        }
      }
    // [a][j][k]: then over b, with B_b(v_j) (v00, v01) or B'_b(v_j) (v10).
    Eigen::Vector3d v00[4][4][4], v01[4][4][4], v10[4][4][4];
    for (int a = 0; a < 4; ++a)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) {
          v00[a][j][k] = v01[a][j][k] = v10[a][j][k] = Eigen::Vector3d::Zero();
          for (int b = 0; b < 4; ++b) {
            v00[a][j][k] += B[j][b] * w0[a][b][k];
            v01[a][j][k] += B[j][b] * w1[a][b][k];
            v10[a][j][k] += D[j][b] * w0[a][b][k];
          }
        }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) {
          Eigen::Vector3d position = Eigen::Vector3d::Zero();
          Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
          for (int a = 0; a < 4; ++a) {
            position += B[i][a] * v00[a][j][k];
            J.col(0) += D[i][a] * v00[a][j][k];
            J.col(1) += B[i][a] * v10[a][j][k];
            J.col(2) += B[i][a] * v01[a][j][k];
          }
          const double det = J.determinant();
          if (!(det > 0)) return fail(badJacobian(t, det));
          mesh.tricubicInverseJacobian.push_back(J.inverse());
          mesh.gaussVolume.push_back(gauss4.weights[i] * gauss4.weights[j] * gauss4.weights[k] *
                                     det);
          mesh.gaussRestPosition.push_back(position);
        }
  }

  for (uint32_t l = 0; l < mesh.numLinear(); ++l) {
    const uint32_t e = mesh.numTricubic() + l;
    const auto& nodes = mesh.linearNodes[l];
    const bool pyramid = mesh.elementType[e] == ElementType::Pyramid;
    const QuadratureRule& ruleW = pyramid ? collapsed : gauss2;
    auto gradientAt = [&](const Eigen::Vector3d& xi, double& det, Eigen::Vector3d& position) {
      double N[8], dN[8][3];
      trilinearShape(xi, N, dN);
      Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
      Eigen::Matrix<double, 8, 3> dNdXi;
      position.setZero();
      for (int a = 0; a < 8; ++a) {
        const Eigen::Vector3d X = mesh.restNodes.row(nodes[a]).transpose();
        position += N[a] * X;
        for (int d = 0; d < 3; ++d) {
          J.col(d) += dN[a][d] * X;
          dNdXi(a, d) = dN[a][d];
        }
      }
      det = J.determinant();
      // dN/dX = dN/dxi * (dX/dxi)^-1
      return LinearShapeGradient(dNdXi * J.inverse());
    };
    double det = 0;
    Eigen::Vector3d position;
    mesh.linearCentreShapeGradient.push_back(gradientAt(Eigen::Vector3d(0.5, 0.5, 0.5), det,
                                                        position));
    if (!(det > 0)) return fail(badJacobian(e, det));
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k) {
          const Eigen::Vector3d xi(gauss2.points[i], gauss2.points[j], ruleW.points[k]);
          mesh.linearShapeGradient.push_back(gradientAt(xi, det, position));
          if (!(det > 0)) return fail(badJacobian(e, det));
          mesh.gaussVolume.push_back(gauss2.weights[i] * gauss2.weights[j] * ruleW.weights[k] *
                                     det);
          mesh.gaussRestPosition.push_back(position);
        }
  }

  mesh.gaussMaterial.assign(mesh.numGaussPoints(), options.material);
  mesh.gaussLame.assign(mesh.numGaussPoints(), lameParameters(options.material));
  return mesh;
}

}  // namespace sculpt
