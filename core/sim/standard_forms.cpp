#include "sim/standard_forms.h"

namespace sculpt {

Points applyScalarMatrix(const SparseMatrix& S, const Points& x) {
  Eigen::MatrixXd columns = x;  // column-major copy for the sparse product
  Points result = S * columns;
  return result;
}

void ElasticForm::prepare(const FormState& x) {
  if (corotated_) model_.elastic().updateRotations(x.nodes);
  else model_.elastic().resetRotations();
}

double ElasticForm::energy(const FormState& x) const { return model_.elastic().energy(x.nodes); }

void ElasticForm::addGradient(const FormState& x, FormGradient& g) const {
  model_.elastic().addGradient(x.nodes, g.nodes);
}

void ElasticForm::addHessianProduct(const FormState&, const FormState& dx, FormGradient& r) const {
  model_.elastic().addHessianProduct(dx.nodes, r.nodes);
}

double InertiaForm::energy(const FormState& x) const {
  const Points d = x.control - predicted_;
  const Points Md = applyScalarMatrix(model_.reducedMass(), d);
  return 0.5 / (h_ * h_) * d.cwiseProduct(Md).sum();
}

void InertiaForm::addGradient(const FormState& x, FormGradient& g) const {
  g.control += applyScalarMatrix(model_.reducedMass(), x.control - predicted_) / (h_ * h_);
}

void InertiaForm::addHessianProduct(const FormState&, const FormState& dx,
                                    FormGradient& r) const {
  r.control += applyScalarMatrix(model_.reducedMass(), dx.control) / (h_ * h_);
}

double DampingForm::energy(const FormState& x) const {
  const Points d = x.control - start_;
  const Points Dd = applyScalarMatrix(model_.reducedDamping(), d);
  return 0.5 / h_ * d.cwiseProduct(Dd).sum();
}

void DampingForm::addGradient(const FormState& x, FormGradient& g) const {
  g.control += applyScalarMatrix(model_.reducedDamping(), x.control - start_) / h_;
}

void DampingForm::addHessianProduct(const FormState&, const FormState& dx,
                                    FormGradient& r) const {
  r.control += applyScalarMatrix(model_.reducedDamping(), dx.control) / h_;
}

const Eigen::VectorXd& GravityForm::weights() const {
  // M~ 1: the mass each control point carries (rows of M~ summed); refreshed with the materials.
  if (weightsVersion_ != model_.massVersion() || weights_.size() == 0) {
    weights_ = model_.reducedMass() * Eigen::VectorXd::Ones(model_.numControlPoints());
    weightsVersion_ = model_.massVersion();
  }
  return weights_;
}

double GravityForm::energy(const FormState& x) const {
  return -weights().dot(x.control * g_);
}

void GravityForm::addGradient(const FormState&, FormGradient& g) const {
  g.control -= weights() * g_.transpose();
}

}  // namespace sculpt
