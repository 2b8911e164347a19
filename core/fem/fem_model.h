#pragma once
// A solid ready to simulate: the control mesh, its subdivision to the simulation level, the
// elements there, the elastic kernel and the reduced (control-point) mass and damping matrices.
// Unknowns are the control points p; nodes are d = A p, node vectors go back with A^T.

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "fem/elastic_kernel.h"
#include "fem/fem_mesh.h"
#include "fem/mass_matrix.h"
#include "mesh/cell_complex.h"
#include "subdiv/mj_refiner.h"
#include "util/progress.h"

namespace sculpt {

struct FemSetup {
  int level = 2;           ///< simulation level K >= 1 (ignored when trilinear)
  bool trilinear = false;  ///< trilinear elements on the control cells themselves (A = I)
  Material material;       ///< initial uniform material
};

class FemModel {
 public:
  /// Subdivides `control` (which must be valid) and builds the elements. Returns nullopt with a
  /// sentence in *error on a bad setting or an inverted element; nullopt without an error when
  /// cancelled through `progress`.
  static std::optional<FemModel> create(const CellComplex& control, const FemSetup& setup,
                                        std::string* error, ProgressReporter* progress = nullptr);

  const FemSetup& setup() const { return setup_; }
  const CellComplex& control() const { return subdivision_->levels.front(); }
  const Points& restControl() const { return control().positions; }
  /// Subdivision levels 0..K (just the control mesh in trilinear mode).
  const Subdivision& subdivision() const { return *subdivision_; }
  const FemMesh& mesh() const { return *mesh_; }
  ElasticKernel& elastic() { return *elastic_; }
  const ElasticKernel& elastic() const { return *elastic_; }
  uint32_t numControlPoints() const { return mesh_->numControlPoints(); }
  uint32_t numNodes() const { return mesh_->numNodes(); }

  /// nodes = A control (#nodes by 3).
  void nodesFromControl(const Points& control, Points& nodes) const;
  /// control += A^T nodeVectors.
  void addToControl(const Points& nodeVectors, Points& control) const;

  const SparseMatrix& stencilMatrix() const { return A_; }
  /// M~ = A^T M A and D~ = A^T D A (scalar, #control square), refreshed after material edits.
  const SparseMatrix& reducedMass() const;
  const SparseMatrix& reducedDamping() const;
  double totalMass() const;

  /// Sets every Gauss sample whose rest position lies within `radius` of `centre` (all of them
  /// when radius is infinite) to `material`, and marks what depends on it for refresh. Returns
  /// the number of samples changed, or -1 (and a sentence in *error) for an invalid material.
  long paintMaterial(const Eigen::Vector3d& centre, double radius, const Material& material,
                     std::string* error = nullptr);
  /// Which fields of a Material a weighted paint writes.
  struct MaterialFields {
    bool density = true;
    bool damping = true;
    bool youngs = true;
    bool poisson = true;
  };
  /// Weighted paint (brushes with falloff): every Gauss sample with w = weight(rest position) > 0
  /// has each selected field f moved towards the target, f + min(w, 1) (f_target - f); w >= 1 sets
  /// it exactly. Samples with w <= 0 (or NaN) are not touched, bit for bit. A blend of two valid
  /// materials is valid. Returns the number of samples with w > 0, or -1 (and a sentence in
  /// *error) for an invalid target.
  long paintMaterial(const std::function<double(const Eigen::Vector3d&)>& weight,
                     const Material& target, const MaterialFields& fields,
                     std::string* error = nullptr);
  /// Sets every Gauss sample's material at once (e.g. restored from a project file: one per
  /// FemMesh Gauss point, in order). Returns false with a sentence in *error, changing nothing,
  /// for a count mismatch or an invalid material.
  bool setMaterials(std::span<const Material> materials, std::string* error = nullptr);
  /// Bumped by every material change (lets solvers know their factorisations are stale).
  uint64_t materialVersion() const { return materialVersion_; }
  /// Bumped only when density or damping change (M~ and D~ then change).
  uint64_t massVersion() const { return massVersion_; }

 private:
  FemModel() = default;
  FemSetup setup_;
  std::unique_ptr<Subdivision> subdivision_;
  std::unique_ptr<FemMesh> mesh_;
  std::unique_ptr<ElasticKernel> elastic_;
  SparseMatrix A_;
  mutable SparseMatrix reducedMass_, reducedDamping_;
  // The Gauss-point weights (field times volume) the matrices were last made from.
  mutable std::vector<double> assembledDensity_, assembledDamping_;
  mutable bool matricesStale_ = true;
  uint64_t materialVersion_ = 0;
  uint64_t massVersion_ = 0;
  void refreshMatrices() const;
  /// Marks what depends on changed material fields for refresh and bumps the versions.
  void refreshAfterMaterialChange(bool massChanged, bool stiffnessChanged);
};

}  // namespace sculpt
