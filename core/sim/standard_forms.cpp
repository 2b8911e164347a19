#include "sim/standard_forms.h"

#include "util/parallel_for.h"

namespace sculpt {

Points applyScalarMatrix(const SparseMatrix& S, const Points& x) {
  if (S.nonZeros() == 0) return Points::Zero(S.rows(), 3);  // no damping: D~ is empty
  if (!S.isCompressed()) return applyScalarMatrix(SparseMatrix(S), x);
  // S is symmetric, so its column i is its row i: each worker sums whole rows of the result.
  // x is copied with a fourth, zero column, so that each nonzero is one four-wide multiply-add
  // (with three scalar ones per nonzero and one sum per row, a product took 1.8x as long).
  using PaddedPoints = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;
  PaddedPoints padded(x.rows(), 4);
  padded.leftCols<3>() = x;
  padded.col(3).setZero();
  Points result(S.rows(), 3);
  const int* begin = S.outerIndexPtr();
  const int* rows = S.innerIndexPtr();
  const double* values = S.valuePtr();
  parallelChunks(uint32_t(S.rows()), 256, [&](uint32_t first, uint32_t last, unsigned) {
    auto term = [&](int k) {
      return values[k] * Eigen::Map<const Eigen::Array4d>(padded.data() + 4 * size_t(rows[k]));
    };
    for (uint32_t i = first; i < last; ++i) {
      // Four partial sums: one would wait for each addition before the next could start.
      Eigen::Array4d sum[4] = {Eigen::Array4d::Zero(), Eigen::Array4d::Zero(),
                               Eigen::Array4d::Zero(), Eigen::Array4d::Zero()};
      int k = begin[i];
      for (; k + 4 <= begin[i + 1]; k += 4)
        for (int j = 0; j < 4; ++j) sum[j] += term(k + j);
      for (; k < begin[i + 1]; ++k) sum[0] += term(k);
      const Eigen::Array4d total = (sum[0] + sum[1]) + (sum[2] + sum[3]);
      result.row(Eigen::Index(i)) = total.head<3>().matrix().transpose();
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
