#pragma once
// An energy term of the simulation ("form"): value, gradient and Hessian-vector product, each
// checked against finite differences in the tests. Forms see both the control points p and the
// nodes d = A p; gradients may land on either level (node parts are projected with A^T once, by
// whoever sums the forms), so a term defined on the nodes never applies A itself.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "mesh/cell_complex.h"

namespace sculpt {

class FemModel;

/// A configuration (or a direction): control points and the nodes A p.
struct FormState {
  const Points& control;
  const Points& nodes;
};

/// A gradient (or a Hessian-vector product) split by level; the total is control + A^T nodes.
struct FormGradient {
  Points control;
  Points nodes;
  void setZero(Eigen::Index numControl, Eigen::Index numNodes) {
    control.setZero(numControl, 3);
    nodes.setZero(numNodes, 3);
  }
};

class Form {
 public:
  virtual ~Form() = default;
  virtual std::string name() const = 0;
  virtual double energy(const FormState& x) const = 0;
  virtual void addGradient(const FormState& x, FormGradient& gradient) const = 0;
  /// result += H(x) dx.
  virtual void addHessianProduct(const FormState& x, const FormState& dx,
                                 FormGradient& result) const = 0;
  /// Called once per step (or Newton iteration) before the other calls: lets a form freeze
  /// what it linearises (the elastic rotations, the contact set).
  virtual void prepare(const FormState& /*x*/) {}
};

using FormList = std::vector<std::unique_ptr<Form>>;

}  // namespace sculpt
