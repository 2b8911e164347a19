#pragma once
// Co-rotated linear elasticity on the elements of a FemMesh (docs/design/local-frame-fem.md).
//
// Per element a rotation R_e (polar decomposition of F at the element centre). With the
// rotations held fixed the energy
//     E(x) = sum_q V_q (mu eps:eps + lambda/2 tr(eps)^2),   eps = sym(R_e^T F_q) - I
// is quadratic in the node positions x; its gradient is R_e K_e (R_e^T x_e - X_e) summed over
// elements (the elastic force with a minus sign) and its Hessian is R_e K_e R_e^T, the usual
// co-rotational stiffness that ignores the derivative of R_e. Tricubic elements are evaluated
// matrix-free with sum factorisation over the 4x4x4 tensor structure; linear elements use their
// stored rest shape-function gradients. Element loops run on all worker threads.
//
// With the Barrier model (fem/elastic_model.h) every Gauss point also carries the inversion
// barrier. Its Hessian is taken at the state of the last rotation update, like the rotations:
// the update records R^T F of every element that has a point below the threshold.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "fem/elastic_model.h"
#include "fem/fem_mesh.h"
#include "fem/node_rows.h"

namespace sculpt {

class ElasticKernel {
 public:
  explicit ElasticKernel(const FemMesh& mesh);
  // The barrier's states point into the kernel's own records.
  ElasticKernel(const ElasticKernel&) = delete;
  ElasticKernel& operator=(const ElasticKernel&) = delete;

  /// R_e from the current node positions (#nodes by 3).
  void updateRotations(const Points& nodes);
  /// updateRotations(nodes), then addGradient(nodes, gradient), in one pass over the elements.
  void updateRotationsAndAddGradient(const Points& nodes, Points& gradient);
  /// R_e = I for every element: plain small-strain linear elasticity.
  void resetRotations();
  const std::vector<Eigen::Matrix3d>& rotations() const { return rotations_; }

  /// While alive, keeps the kernel's rotations (the next update's warm start): they are put back
  /// when it ends. For queries that find a state's own rotations (an energy asked for, a field
  /// shown): otherwise asking would change the last bits of every later step.
  class WarmStartKept {
   public:
    explicit WarmStartKept(ElasticKernel& kernel) : kernel_(kernel), kept_(kernel.rotations_) {}
    ~WarmStartKept() { kernel_.rotations_ = std::move(kept_); }
    WarmStartKept(const WarmStartKept&) = delete;
    WarmStartKept& operator=(const WarmStartKept&) = delete;

   private:
    ElasticKernel& kernel_;
    std::vector<Eigen::Matrix3d> kept_;
  };

  /// E(nodes) with the current rotations.
  double energy(const Points& nodes) const;
  /// The terms of E(nodes), one per element (with the current rotations): energies[e] is the
  /// elastic energy of element e (J); they sum to energy(nodes). For strain energy densities.
  void elementEnergies(const Points& nodes, std::vector<double>& energies) const;
  /// gradient += dE/dx at `nodes` (= minus the elastic node forces).
  void addGradient(const Points& nodes, Points& gradient) const;
  /// result += H dx, H the Hessian of E (rotations fixed).
  void addHessianProduct(const Points& dx, Points& result) const;

  /// The energy of the elements: Corotated until set (the Simulator sets its settings' model).
  void setModel(ElasticModel model, const InversionBarrier& barrier = {});
  ElasticModel model() const { return model_; }
  const InversionBarrier& barrier() const { return barrier_; }
  /// Elements with a Gauss point below the barrier's threshold at the last rotation update.
  uint32_t barrierElements() const;

  /// det F over every Gauss point at `nodes` (any model): how compressed, or inverted, it is.
  struct Jacobians {
    double min = 1.0;               ///< the smallest det F (rest: 1; <= 0: inside out)
    uint32_t invertedPoints = 0;    ///< Gauss points with det F <= 0
    uint32_t invertedElements = 0;  ///< elements with such a point
  };
  Jacobians jacobians(const Points& nodes) const;

  const FemMesh& mesh() const { return mesh_; }
  /// Re-reads the Gauss-point materials (after FemMesh::gaussLame changed).
  void refreshMaterial();

 private:
  enum class Mode { Gradient, HessianProduct };
  // One worker's recorded barrier states: element ids and their R^T F blocks.
  struct BarrierRecord {
    std::vector<uint32_t> elements;
    std::vector<double> states;
  };
  // Runs the element kernels; accumulates into `out` when non-null and returns the energy when
  // `withEnergy` (gradient mode only), storing each element's term in `perElement` if non-null.
  // With `newRotations` (gradient mode; rotations_.data()) each element's rotation is first
  // set from x there. With `records` (resized to one per worker) the barrier states of the
  // elements below its threshold (every element with `recordAll`) are recorded there.
  double run(const Points& x, Mode mode, Points* out, bool withEnergy,
             double* perElement = nullptr, Eigen::Matrix3d* newRotations = nullptr,
             std::vector<BarrierRecord>* records = nullptr, bool recordAll = false) const;
  // barrierState_ from the workers' records of a rotation update (barrierRecords_).
  void keepBarrierRecords() const;
  // Records the barrier's state at the last updateRotations' nodes if it has not been yet: that
  // update only finds the rotations (it mostly precedes an energy query), and the record costs a
  // whole element pass, so it is made when a Hessian product first needs it.
  void refreshBarrier() const;
  // Gathers element e's node values of x into ue in the kernels' coordinate-major layout;
  // returns the node count.
  uint32_t gatherElement(uint32_t e, const NodeRows& x, double* ue) const;
  // Element e's nodes in the kernel's numbering.
  const uint32_t* elementNodes(uint32_t e) const;
  // source_ = x (#nodes by 3, mesh numbering) in the kernel's numbering, minus the rest
  // positions when `displacement`.
  void loadSource(const Points& x, bool displacement) const;
  // F at the centre of element e from its gathered displacements.
  Eigen::Matrix3d centreDeformationGradient(uint32_t e, const double* ue) const;
  // newRotations[first + k] for the `count` (<= 4) elements from `first` on, from their gathered
  // displacements ue[k], warm-started from rotations_ (which newRotations may be).
  void updateGroupRotations(uint32_t first, int count, const double (*ue)[192],
                            Eigen::Matrix3d* newRotations) const;

  const FemMesh& mesh_;
  std::vector<Eigen::Matrix3d> rotations_;
  ElasticModel model_ = ElasticModel::Corotated;  // the Simulator sets the scene's
  InversionBarrier barrier_;
  // The last rotation update's records (h of barrier_stress.h, or R^T F with the exact
  // Hessian), and per element where its record starts in them (null: nothing recorded; empty:
  // no element recorded).
  mutable std::vector<BarrierRecord> barrierRecords_;
  mutable std::vector<const double*> barrierState_;
  mutable uint32_t barrierElements_ = 0;
  mutable bool barrierStale_ = false;  // barrierNodes_ are newer than the record
  Points barrierNodes_;
  mutable std::vector<NodeRows> workerBuffers_;
  mutable NodeRows source_;  // the pass's input: x - rest (gradient mode) or the direction
  // Rows of the node vectors above are in the kernel's numbering: meshNode_[k] is the mesh
  // node of row k, and elementNodes_ holds every element's rows (64 per tricubic element, then
  // 8 per linear one).
  std::vector<uint32_t> meshNode_, elementNodes_;
  NodeRows restRows_;
  // Tricubic rest data packed for tricubicElementKernel.
  // Per element one block of rest data (tricubicRestSize in tricubic_kernel.h).
  std::vector<double> tricubicRest_;
  std::vector<size_t> tricubicRestOffset_;  // element's start in tricubicRest_, then the end
  std::vector<bool> tricubicAffine_;        // one block of inverse Jacobians
  // An affine element aligned with the axes: per column of its inverse Jacobian, the row of the
  // one nonzero (tricubic_kernel.h); -1 in the first entry otherwise.
  std::vector<std::array<int8_t, 3>> tricubicAxisRows_;
  std::vector<double> linearShapeGradient_, linearVolumeLambda_, linearVolumeMu_;  // [l][a*3+c][q]
};

}  // namespace sculpt
