#pragma once
// The forms every simulation has: elasticity, inertia and damping of the implicit step, gravity.

#include "fem/fem_model.h"
#include "sim/form.h"

namespace sculpt {

/// Co-rotated elasticity on the nodes; prepare() updates the element rotations (unless the
/// model is linear), after which energy, gradient and Hessian are exact for fixed rotations.
class ElasticForm : public Form {
 public:
  ElasticForm(FemModel& model, bool corotated) : model_(model), corotated_(corotated) {}
  std::string name() const override { return "elastic"; }
  void prepare(const FormState& x) override;
  /// prepare(x) followed by addGradient(x, g), in one pass over the elements.
  void prepareAndAddGradient(const FormState& x, FormGradient& g);
  double energy(const FormState& x) const override;
  void addGradient(const FormState& x, FormGradient& g) const override;
  void addHessianProduct(const FormState& x, const FormState& dx, FormGradient& r) const override;

 private:
  FemModel& model_;
  bool corotated_;
};

/// (scale / 2) (p - r)^T S (p - r) with S the reduced mass or damping matrix (scalar, each
/// coordinate) and r a reference configuration. The reference starts at the rest shape.
class QuadraticControlForm : public Form {
 public:
  QuadraticControlForm(const FemModel& model, MassField field, double scale);
  void setReference(const Points& reference) { reference_ = reference; }
  double energy(const FormState& x) const override;
  void addGradient(const FormState& x, FormGradient& g) const override;
  void addHessianProduct(const FormState& x, const FormState& dx, FormGradient& r) const override;
  /// The Hessian is scale() * matrix() on each coordinate.
  const SparseMatrix& matrix() const;
  double scale() const { return scale_; }

 private:
  const FemModel& model_;
  MassField field_;
  double scale_;
  Points reference_;
};

/// (1 / (2 h^2)) (p - p^)^T M~ (p - p^): the inertia of a backward Euler step, p^ = p_n + h v_n.
class InertiaForm : public QuadraticControlForm {
 public:
  InertiaForm(const FemModel& model, double h)
      : QuadraticControlForm(model, MassField::Density, 1.0 / (h * h)) {}
  std::string name() const override { return "inertia"; }
  void setPrediction(const Points& predicted) { setReference(predicted); }
};

/// (1 / (2 h)) (p - p_n)^T D~ (p - p_n): Rayleigh's dissipation of a backward Euler step.
class DampingForm : public QuadraticControlForm {
 public:
  DampingForm(const FemModel& model, double h)
      : QuadraticControlForm(model, MassField::Damping, 1.0 / h) {}
  std::string name() const override { return "damping"; }
  void setStart(const Points& start) { setReference(start); }
};

/// -sum g . (M~ p): uniform gravity g (m/s^2) on the consistent mass (A 1 = 1, so this is the
/// weight of every node projected with A^T).
class GravityForm : public Form {
 public:
  GravityForm(const FemModel& model, const Eigen::Vector3d& g) : model_(model), g_(g) {}
  std::string name() const override { return "gravity"; }
  double energy(const FormState& x) const override;
  void addGradient(const FormState& x, FormGradient& g) const override;
  void addHessianProduct(const FormState&, const FormState&, FormGradient&) const override {}

 private:
  const Eigen::VectorXd& weights() const;
  const FemModel& model_;
  Eigen::Vector3d g_;
  mutable Eigen::VectorXd weights_;
  mutable uint64_t weightsVersion_ = 0;
};

/// Symmetric scalar matrix S (a reduced mass or damping matrix) applied to each coordinate
/// column of an N by 3 array, rows split over the workers (those matrices couple every control
/// point with hundreds of others).
Points applyScalarMatrix(const SparseMatrix& S, const Points& x);

}  // namespace sculpt

namespace sculpt {

/// -sum_i f_i . p_i: generalised forces applied directly to control points (the command line's
/// --force BOX spreads a total force equally over the control points in a box).
class ControlForceForm : public Form {
 public:
  explicit ControlForceForm(Points forces) : forces_(std::move(forces)) {}
  std::string name() const override { return "control forces"; }
  const Points& forces() const { return forces_; }
  double energy(const FormState& x) const override {
    return -x.control.cwiseProduct(forces_).sum();
  }
  void addGradient(const FormState&, FormGradient& g) const override { g.control -= forces_; }
  void addHessianProduct(const FormState&, const FormState&, FormGradient&) const override {}

 private:
  Points forces_;
};

}  // namespace sculpt
