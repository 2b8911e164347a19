#pragma once
// Meshes and measures for the topology-editing tests (tests/edit): the bundled block3 and
// house_small, two parts side by side, and the total volume.

#include <filesystem>

#include "io/control_mesh_json.h"
#include "mesh/validation.h"
#include "support/fem_builders.h"
#include "support/mesh_builders.h"

namespace sculpt::test {

/// tests/data/house_small.json: a unit hexahedron with a pyramid roof, the bottom square creased
/// and its corners tagged.
inline CellComplex houseSmall() {
  return loadControlMeshJson(std::filesystem::path(SCULPT_SOURCE_DIR) / "tests" / "data" /
                             "house_small.json");
}

/// `a` followed by `b` moved by `offset`, as two separate parts (b's vertex ids, cells and tags
/// shifted after a's).
inline CellComplex twoParts(const CellComplex& a, const CellComplex& b,
                            const Eigen::Vector3d& offset) {
  CellComplex m = a;
  const uint32_t shift = a.numVertices();
  m.positions.conservativeResize(a.positions.rows() + b.positions.rows(), 3);
  for (Eigen::Index i = 0; i < b.positions.rows(); ++i)
    m.positions.row(shift + i) = b.positions.row(i) + offset.transpose();
  for (uint32_t c = 0; c < b.numCells(); ++c) {
    Loops loops;
    for (uint32_t j = 0; j < b.numFacesOfCell(c); ++j) {
      std::vector<uint32_t> loop;
      for (uint32_t v : b.cellFace(c, j)) loop.push_back(v + shift);
      loops.push_back(loop);
    }
    m.addCell(loops);
  }
  for (const auto& [p, q] : b.creases) m.creases.push_back({p + shift, q + shift});
  for (uint32_t v : b.corners) m.corners.push_back(v + shift);
  return m;
}

/// Sum of the signed cell volumes (m^3).
inline double totalVolume(const CellComplex& m) {
  double volume = 0;
  for (uint32_t c = 0; c < m.numCells(); ++c) volume += cellVolume(m, c);
  return volume;
}

/// True when validate() reports no error; the first error otherwise goes to the test log.
inline ::testing::AssertionResult validMesh(const CellComplex& m) {
  for (const ValidationIssue& issue : validate(m))
    if (issue.severity == ValidationIssue::Severity::Error)
      return ::testing::AssertionFailure() << issue.message;
  return ::testing::AssertionSuccess();
}

}  // namespace sculpt::test
