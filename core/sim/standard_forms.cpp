#include "sim/standard_forms.h"

#include "util/parallel_for.h"

namespace sculpt {

Points applyScalarMatrix(const SparseMatrix& S, const Points& x) {
  // S is symmetric, so its column i is its row i: each worker sums whole rows of the result.
  Points result(S.rows(), 3);
  parallelChunks(uint32_t(S.rows()), 256, [&](uint32_t begin, uint32_t end, unsigned) {
    for (uint32_t i = begin; i < end; ++i) {
      double sum[3] = {0, 0, 0};
      for (SparseMatrix::InnerIterator it(S, Eigen::Index(i)); it; ++it) {
        const double* row = x.row(it.row()).data();
        sum[0] += it.value() * row[0];
        sum[1] += it.value() * row[1];
        sum[2] += it.value() * row[2];
      }
      result.row(Eigen::Index(i)) << sum[0], sum[1], sum[2];
    }
  });
  return result;
}

void ElasticForm::prepare(const FormState& x) {
  if (corotated_) model_.elastic().updateRotations(x.nodes);
  else model_.elastic().resetRotations();
}

void ElasticForm::prepareAndAddGradient(const FormState& x, FormGradient& g) {
  if (!corotated_) {
    prepare(x);
    addGradient(x, g);
    return;
  }
  model_.elastic().updateRotationsAndAddGradient(x.nodes, g.nodes);
}

double ElasticForm::energy(const FormState& x) const { return model_.elastic().energy(x.nodes); }

void ElasticForm::addGradient(const FormState& x, FormGradient& g) const {
  model_.elastic().addGradient(x.nodes, g.nodes);
}

void ElasticForm::addHessianProduct(const FormState&, const FormState& dx, FormGradient& r) const {
  model_.elastic().addHessianProduct(dx.nodes, r.nodes);
}

QuadraticControlForm::QuadraticControlForm(const FemModel& model, MassField field, double scale)
    : model_(model), field_(field), scale_(scale), reference_(model.restControl()) {}

const SparseMatrix& QuadraticControlForm::matrix() const {
  return field_ == MassField::Density ? model_.reducedMass() : model_.reducedDamping();
}

double QuadraticControlForm::energy(const FormState& x) const {
  const Points d = x.control - reference_;
  return 0.5 * scale_ * d.cwiseProduct(applyScalarMatrix(matrix(), d)).sum();
}

void QuadraticControlForm::addGradient(const FormState& x, FormGradient& g) const {
  g.control += scale_ * applyScalarMatrix(matrix(), x.control - reference_);
}

void QuadraticControlForm::addHessianProduct(const FormState&, const FormState& dx,
                                             FormGradient& r) const {
  r.control += scale_ * applyScalarMatrix(matrix(), dx.control);
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
