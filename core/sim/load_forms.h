#pragma once
// External loads as forms (docs/design/local-frame-fem.md "Loads and constraints"): a force at any
// material point, a penalty spring from a material point to a target (mouse or stylus pull),
// pressure on the boundary (inflate, deflate) and penalty contact with a ground half-space.
//
// Every constructor and setter checks its inputs and throws std::invalid_argument with a sentence
// naming the bad value. A form keeps a reference to its model: the model must outlive it and must
// not be moved while the form exists.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "fem/fem_model.h"
#include "sim/form.h"
#include "sim/material_point.h"

namespace sculpt {

/// A constant force f (N) at a material point: energy -f . x(point), x(point) = sum w_i p_i on the
/// control points (the weights are precomputed). Linear: the Hessian is zero.
class PointForceForm : public Form {
 public:
  PointForceForm(const FemModel& model, const MaterialPoint& point, const Eigen::Vector3d& force);
  std::string name() const override { return "point force"; }
  void setForce(const Eigen::Vector3d& force);
  const Eigen::Vector3d& force() const { return force_; }
  const MaterialPoint& point() const { return point_; }
  /// Current position of the point for control points p.
  Eigen::Vector3d position(const Points& control) const;

  double energy(const FormState& x) const override;
  void addGradient(const FormState& x, FormGradient& g) const override;
  void addHessianProduct(const FormState&, const FormState&, FormGradient&) const override {}

 private:
  MaterialPoint point_;
  std::vector<std::pair<uint32_t, double>> weights_;  // onto control points
  Eigen::Vector3d force_;
};

/// A zero-length spring of stiffness k (N/m) from a material point to a target:
/// energy k/2 |x(point) - target|^2, on the control points. Exact Hessian k w w^T (x3).
class PenaltySpringForm : public Form {
 public:
  PenaltySpringForm(const FemModel& model, const MaterialPoint& point,
                    const Eigen::Vector3d& target, double stiffness);
  std::string name() const override { return "penalty spring"; }
  void setTarget(const Eigen::Vector3d& target);
  void setStiffness(double stiffness);
  const Eigen::Vector3d& target() const { return target_; }
  double stiffness() const { return stiffness_; }
  const MaterialPoint& point() const { return point_; }
  Eigen::Vector3d position(const Points& control) const;

  double energy(const FormState& x) const override;
  void addGradient(const FormState& x, FormGradient& g) const override;
  void addHessianProduct(const FormState& x, const FormState& dx, FormGradient& r) const override;

 private:
  MaterialPoint point_;
  std::vector<std::pair<uint32_t, double>> weights_;
  Eigen::Vector3d target_;
  double stiffness_;
};

/// The part of the boundary a pressure acts on: faces whose rest centroid lies within `radius`
/// of `centre` (radius infinity, the default: the whole boundary).
struct SphereRegion {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = std::numeric_limits<double>::infinity();
};

/// The boundary faces of the finest level whose rest centroid lies in `region`, split into
/// triangles of lattice node ids with outward orientation: each quadrilateral into (v0,v1,v2),
/// (v0,v2,v3), a larger polygon fanned from v0.
std::vector<std::array<uint32_t, 3>> boundaryTriangles(const FemModel& model,
                                                       const SphereRegion& region = {});

/// Pressure P (Pa) on the selected boundary faces of the finest level: energy -P V_region(x),
/// V_region = sum over selected faces of (1/3) integral x . n dA on the faceted surface (each
/// quadrilateral split into the triangles (v0,v1,v2), (v0,v2,v3), a larger polygon fanned from
/// v0), triangle term (1/6) x0 . (x1 x x2), normals outward. For the whole closed boundary
/// V_region is the enclosed volume. Positive pressure inflates. Acts on the lattice nodes; the
/// gradient and Hessian-vector product are exact for this definition.
class PressureForm : public Form {
 public:
  PressureForm(const FemModel& model, double pressure, const SphereRegion& region = {});
  std::string name() const override { return "pressure"; }
  void setPressure(double pressure);
  double pressure() const { return pressure_; }
  /// Number of triangles the selected faces were split into.
  size_t numTriangles() const { return triangles_.size(); }
  /// V_region for node positions `nodes` (m^3).
  double regionVolume(const Points& nodes) const;

  double energy(const FormState& x) const override;
  void addGradient(const FormState& x, FormGradient& g) const override;
  void addHessianProduct(const FormState& x, const FormState& dx, FormGradient& r) const override;

 private:
  std::vector<std::array<uint32_t, 3>> triangles_;  // lattice node ids, outward
  double pressure_;
};

/// Penalty contact with the half-space n . x >= offset (n normalised by the constructor, offset
/// in metres along it) for the boundary lattice nodes of the finest level:
/// energy k/2 sum_i a_i max(0, offset - n . x_i)^2, a_i = 1/m of the rest area of every incident
/// boundary m-gon (so the a_i add up to the boundary area) and k in N/m^3 (a pressure per metre of
/// penetration). The gradient is exact; the Hessian-vector product uses the nodes in contact at x
/// (exact away from the kink n . x_i = offset).
class GroundContactForm : public Form {
 public:
  GroundContactForm(const FemModel& model, const Eigen::Vector3d& normal, double offset,
                    double stiffness);
  std::string name() const override { return "ground contact"; }
  void setStiffness(double stiffness);
  const Eigen::Vector3d& normal() const { return normal_; }
  double offset() const { return offset_; }
  double stiffness() const { return stiffness_; }
  /// Boundary lattice nodes and their area weights (m^2).
  const std::vector<std::pair<uint32_t, double>>& nodeAreas() const { return nodeAreas_; }
  /// Number of nodes with n . x_i < offset.
  size_t numInContact(const Points& nodes) const;

  double energy(const FormState& x) const override;
  void addGradient(const FormState& x, FormGradient& g) const override;
  void addHessianProduct(const FormState& x, const FormState& dx, FormGradient& r) const override;

 private:
  std::vector<std::pair<uint32_t, double>> nodeAreas_;
  Eigen::Vector3d normal_;
  double offset_;
  double stiffness_;
};

}  // namespace sculpt
