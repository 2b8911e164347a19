#pragma once
// A reduced stiffness (the stand-in or the elements' own rest stiffness) kept with the materials
// it was assembled for, so that a factor for new materials assembles only the elements whose
// materials changed. Every element matrix is linear in its Gauss points' lambda and mu, so
// S(new) = S(old) + S(new - old), the last term over the changed elements only (docs/fem.md,
// "A new factor assembles only what was painted").

#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

#include "fem/fem_mesh.h"
#include "fem/mass_matrix.h"

namespace sculpt {

struct AssembledStiffness {
  SparseMatrix matrix;                ///< reduced to the control points: 3N x 3N
  std::vector<LameParameters> lame;   ///< the Gauss-point materials it was assembled for
  bool restStiffness = false;         ///< the elements' own rest stiffness, not the stand-in
};

/// The reduced stiffness of the kind asked for, assembled whole, or without the elements that
/// have skip[e] (none when skip is empty). Empty once `stop` is set.
SparseMatrix assembleStiffness(const FemMesh& mesh, std::span<const LameParameters> lame,
                               const SparseMatrix& A, bool restStiffness,
                               const std::atomic<bool>* stop = nullptr,
                               std::span<const uint8_t> skip = {});

/// The reduced stiffness of `base`'s kind at the materials `lame`: base's matrix plus the share
/// of the elements whose materials changed, or assembled whole where most of them did.
SparseMatrix stiffnessAt(const FemMesh& mesh, const AssembledStiffness& base,
                         std::span<const LameParameters> lame, const SparseMatrix& A,
                         const std::atomic<bool>* stop = nullptr);

}  // namespace sculpt
