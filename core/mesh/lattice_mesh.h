#pragma once
// Regular lattices of cubes as VolumeMeshes: the meshes of the convergence experiments and of the
// built-in benchmark scene.

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "mesh/volume_mesh.h"

namespace sculpt {

struct LatticeSpec {
  std::array<uint32_t, 3> cubes{1, 1, 1};   ///< cubes along x, y, z
  double spacing = 1.0;                     ///< cube edge length h
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< corner of cube (0,0,0)
};

/// Node id of lattice point (i, j, k), 0 <= i <= cubes[0] etc.
uint32_t latticeNode(const LatticeSpec& spec, uint32_t i, uint32_t j, uint32_t k);

/// Hexahedral lattice: one trilinear hexahedron per cube, cube (i,j,k) is cell
/// i + cubes[0] * (j + cubes[1] * k).
VolumeMesh hexLattice(const LatticeSpec& spec);

/// Conforming tetrahedral lattice: each cube split into the 6 tetrahedra around its main diagonal
/// (Freudenthal–Kuhn), cube (i,j,k) owning cells 6 c .. 6 c + 5 with c as above. Every tetrahedron
/// is positively oriented.
VolumeMesh tetLattice(const LatticeSpec& spec);

/// Moves every interior node by up to `fraction` of the spacing in a random direction (seeded),
/// keeping boundary nodes on the box so the lattice still fills it. Cells stay valid for
/// fraction <= 0.2.
void jitterLattice(VolumeMesh& mesh, const LatticeSpec& spec, double fraction, uint32_t seed);

}  // namespace sculpt
