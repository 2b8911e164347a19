#include "sim/assembled_stiffness.h"

#include <stdexcept>

#include "sim/linear_stiffness.h"
#include "sim/rest_stiffness.h"

namespace sculpt {

SparseMatrix assembleStiffness(const FemMesh& mesh, std::span<const LameParameters> lame,
                               const SparseMatrix& A, bool restStiffness,
                               const std::atomic<bool>* stop, std::span<const uint8_t> skip) {
  return restStiffness ? reducedRestStiffness(mesh, lame, A, stop, skip)
                       : reducedLinearStiffness(mesh, lame, A, skip);
}

SparseMatrix stiffnessAt(const FemMesh& mesh, const AssembledStiffness& base,
                         std::span<const LameParameters> lame, const SparseMatrix& A,
                         const std::atomic<bool>* stop) {
  if (base.lame.size() != lame.size() || lame.size() != mesh.gaussLame.size())
    throw std::invalid_argument("stiffnessAt: materials of another mesh");
  std::vector<LameParameters> change(lame.size());
  std::vector<uint8_t> unchanged(mesh.numElements(), 1);
  uint32_t changed = 0;
  for (uint32_t e = 0; e < mesh.numElements(); ++e) {
    const uint32_t begin = mesh.gaussBegin(e);
    for (uint32_t q = begin; q < begin + mesh.gaussCount(e); ++q) {
      change[q] = {lame[q].lambda - base.lame[q].lambda, lame[q].mu - base.lame[q].mu};
      if (change[q].lambda != 0 || change[q].mu != 0) unchanged[e] = 0;
    }
    changed += 1 - unchanged[e];
  }
  if (changed == 0) return base.matrix;
  if (2 * changed > mesh.numElements())
    return assembleStiffness(mesh, lame, A, base.restStiffness, stop);
  const SparseMatrix share =
      assembleStiffness(mesh, change, A, base.restStiffness, stop, unchanged);
  if (stop && *stop) return {};
  return base.matrix + share;
}

}  // namespace sculpt
