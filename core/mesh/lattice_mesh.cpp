#include "mesh/lattice_mesh.h"

#include <algorithm>
#include <random>

namespace sculpt {
namespace {

VolumeMesh latticeNodes(const LatticeSpec& spec) {
  VolumeMesh mesh;
  const uint32_t nx = spec.cubes[0] + 1, ny = spec.cubes[1] + 1, nz = spec.cubes[2] + 1;
  mesh.positions.resize(static_cast<Eigen::Index>(nx) * ny * nz, 3);
  for (uint32_t k = 0; k < nz; ++k)
    for (uint32_t j = 0; j < ny; ++j)
      for (uint32_t i = 0; i < nx; ++i)
        mesh.positions.row(latticeNode(spec, i, j, k)) =
            (spec.origin + spec.spacing * Eigen::Vector3d(i, j, k)).transpose();
  return mesh;
}

}  // namespace

uint32_t latticeNode(const LatticeSpec& spec, uint32_t i, uint32_t j, uint32_t k) {
  return i + (spec.cubes[0] + 1) * (j + (spec.cubes[1] + 1) * k);
}

VolumeMesh hexLattice(const LatticeSpec& spec) {
  VolumeMesh mesh = latticeNodes(spec);
  for (uint32_t k = 0; k < spec.cubes[2]; ++k)
    for (uint32_t j = 0; j < spec.cubes[1]; ++j)
      for (uint32_t i = 0; i < spec.cubes[0]; ++i) {
        const auto n = [&](uint32_t a, uint32_t b, uint32_t c) {
          return latticeNode(spec, i + a, j + b, k + c);
        };
        mesh.addHexahedron({n(0, 0, 0), n(1, 0, 0), n(1, 1, 0), n(0, 1, 0), n(0, 0, 1),
                            n(1, 0, 1), n(1, 1, 1), n(0, 1, 1)});
      }
  return mesh;
}

VolumeMesh tetLattice(const LatticeSpec& spec) {
  VolumeMesh mesh = latticeNodes(spec);
  // Freudenthal–Kuhn: for each ordering of the axes, walk from corner (0,0,0) to (1,1,1) one
  // axis at a time; the four corners visited form a tetrahedron. Neighbouring cubes cut their
  // shared faces along the same diagonal, so the lattice is conforming.
  std::array<int, 3> axes{0, 1, 2};
  std::array<std::array<int, 3>, 6> orders;
  for (int p = 0; p < 6; ++p) {
    orders[p] = axes;
    std::next_permutation(axes.begin(), axes.end());
  }
  for (uint32_t k = 0; k < spec.cubes[2]; ++k)
    for (uint32_t j = 0; j < spec.cubes[1]; ++j)
      for (uint32_t i = 0; i < spec.cubes[0]; ++i)
        for (const auto& order : orders) {
          std::array<uint32_t, 3> corner{0, 0, 0};
          std::array<uint32_t, 4> tet;
          tet[0] = latticeNode(spec, i, j, k);
          for (int step = 0; step < 3; ++step) {
            corner[order[step]] = 1;
            tet[step + 1] = latticeNode(spec, i + corner[0], j + corner[1], k + corner[2]);
          }
          addPositiveTetrahedron(mesh, tet);
        }
  return mesh;
}

void jitterLattice(VolumeMesh& mesh, const LatticeSpec& spec, double fraction, uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (uint32_t k = 1; k < spec.cubes[2]; ++k)
    for (uint32_t j = 1; j < spec.cubes[1]; ++j)
      for (uint32_t i = 1; i < spec.cubes[0]; ++i) {
        Eigen::Vector3d direction(gauss(random), gauss(random), gauss(random));
        direction.normalize();
        mesh.positions.row(latticeNode(spec, i, j, k)) +=
            (fraction * spec.spacing * uniform(random) * direction).transpose();
      }
}

}  // namespace sculpt
