#include "embed/kelvinlet.h"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sculpt {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

Matrix3d crossMatrix(const Vector3d& q) {
  Matrix3d m;
  m << 0.0, -q.z(), q.y(), q.z(), 0.0, -q.x(), -q.y(), q.x(), 0.0;
  return m;
}

void requireFinite(bool finite, const char* what) {
  if (!finite) throw std::invalid_argument(std::string("RegularizedKelvinlet: ") + what);
}

}  // namespace

RegularizedKelvinlet::RegularizedKelvinlet(Kind kind, const Vector3d& centre, double eps,
                                           KelvinletMaterial material)
    : kind_(kind), centre_(centre), eps_(eps), material_(material) {
  requireFinite(centre.allFinite(), "centre must be finite");
  requireFinite(std::isfinite(eps) && eps > 0.0, "eps must be finite and positive");
  requireFinite(std::isfinite(material.shearModulus) && material.shearModulus > 0.0,
                "shear modulus must be finite and positive");
  requireFinite(material.poissonRatio > -1.0 && material.poissonRatio < 0.5,
                "Poisson ratio must lie in (-1, 0.5)");
  a_ = 1.0 / (4.0 * std::numbers::pi * material.shearModulus);
  b_ = a_ / (4.0 * (1.0 - material.poissonRatio));
}

RegularizedKelvinlet RegularizedKelvinlet::grab(const Vector3d& centre, const Vector3d& force,
                                                double eps, KelvinletMaterial material) {
  requireFinite(force.allFinite(), "force must be finite");
  RegularizedKelvinlet k(Kind::kGrab, centre, eps, material);
  k.force_ = force;
  return k;
}

RegularizedKelvinlet RegularizedKelvinlet::affine(const Vector3d& centre, const Matrix3d& F,
                                                  double eps, KelvinletMaterial material) {
  requireFinite(F.allFinite(), "F must be finite");
  RegularizedKelvinlet k(Kind::kAffine, centre, eps, material);
  k.F_ = F;
  return k;
}

RegularizedKelvinlet RegularizedKelvinlet::twist(const Vector3d& centre, const Vector3d& q,
                                                 double eps, KelvinletMaterial material) {
  requireFinite(q.allFinite(), "twist axis must be finite");
  RegularizedKelvinlet k(Kind::kTwist, centre, eps, material);
  k.q_ = q;
  k.F_ = crossMatrix(q);
  return k;
}

RegularizedKelvinlet RegularizedKelvinlet::scale(const Vector3d& centre, double s, double eps,
                                                 KelvinletMaterial material) {
  requireFinite(std::isfinite(s), "scale must be finite");
  RegularizedKelvinlet k(Kind::kScale, centre, eps, material);
  k.s_ = s;
  k.F_ = s * Matrix3d::Identity();
  return k;
}

RegularizedKelvinlet RegularizedKelvinlet::pinch(const Vector3d& centre,
                                                 const Matrix3d& symmetricTraceless, double eps,
                                                 KelvinletMaterial material) {
  const Matrix3d& F = symmetricTraceless;
  requireFinite(F.allFinite(), "pinch matrix must be finite");
  const double tolerance = 1e-12 * F.norm();
  if ((F - F.transpose()).norm() > tolerance || std::abs(F.trace()) > tolerance) {
    throw std::invalid_argument(
        "RegularizedKelvinlet::pinch: the matrix must be symmetric with "
        "zero trace");
  }
  RegularizedKelvinlet k(Kind::kPinch, centre, eps, material);
  k.F_ = F;
  return k;
}

Vector3d RegularizedKelvinlet::displacement(const Vector3d& X) const {
  // Distances: r, r_e and the powers the closed forms use
  const Vector3d r = X - centre_;
  const double eps2 = eps_ * eps_;
  const double re = std::sqrt(r.squaredNorm() + eps2);
  const double re3 = re * re * re;
  const double re5 = re3 * re * re;
  const double a = a_;
  const double b = b_;
  switch (kind_) {
    case Kind::kGrab:
      return ((a - b) / re + a * eps2 / (2.0 * re3)) * force_ + (b / re3) * r.dot(force_) * r;
    case Kind::kTwist:
      return -a * (1.0 / re3 + 1.5 * eps2 / re5) * q_.cross(r);
    case Kind::kScale:
      return (2.0 * b - a) * (1.0 / re3 + 1.5 * eps2 / re5) * s_ * r;
    case Kind::kPinch: {
      const Vector3d Fr = F_ * r;
      return ((2.0 * b - a) / re3) * Fr - (1.5 / re5) * (2.0 * b * r.dot(Fr) * r + a * eps2 * Fr);
    }
    case Kind::kAffine:
      break;
  }
  // General affine load: sum_j d/dr_j of the grab field with force F e_j
  const Vector3d Fr = F_ * r;
  return -(a - b) / re3 * Fr + (b / re3) * (F_.transpose() * r + F_.trace() * r) -
         (3.0 * b / re5) * r.dot(Fr) * r - (1.5 * a * eps2 / re5) * Fr;
}

Matrix3d RegularizedKelvinlet::displacementGradient(const Vector3d& X) const {
  // Each closed form is a sum of radial coefficients c(r_e) times polynomials in r; the chain
  // rule uses d r_e / d r = r / r_e, so the derivatives appear divided by r_e.
  const Vector3d r = X - centre_;
  const double eps2 = eps_ * eps_;
  const double re2 = r.squaredNorm() + eps2;
  const double re = std::sqrt(re2);
  const double re3 = re2 * re;
  const double re5 = re3 * re2;
  const double re7 = re5 * re2;
  const double a = a_;
  const double b = b_;
  // Coefficients shared by both fields: alpha = d/dr_e of the grab's isotropic part over r_e,
  // beta = b / r_e^3 and their derivatives over r_e
  const double alpha = -(a - b) / re3 - 1.5 * a * eps2 / re5;
  const double dAlpha = 3.0 * (a - b) / re5 + 7.5 * a * eps2 / re7;
  const double beta = b / re3;
  const double dBeta = -3.0 * b / re5;
  const Matrix3d I = Matrix3d::Identity();

  if (kind_ == Kind::kGrab) {
    // u = A(r_e) f + beta (r . f) r
    const double rf = r.dot(force_);
    return alpha * force_ * r.transpose() + beta * (rf * I + r * force_.transpose()) +
           dBeta * rf * r * r.transpose();
  }

  // u = alpha F r + beta (F^T r + tr F r) + gamma (r^T F r) r, gamma = -3 b / r_e^5
  const double gamma = -3.0 * b / re5;
  const double dGamma = 15.0 * b / re7;
  const double trF = F_.trace();
  const Vector3d Fr = F_ * r;
  const Vector3d FTr = F_.transpose() * r;
  const double rFr = r.dot(Fr);
  return alpha * F_ + beta * (F_.transpose() + trF * I) + gamma * rFr * I +
         dAlpha * Fr * r.transpose() + dBeta * (FTr + trF * r) * r.transpose() +
         gamma * r * (Fr + FTr).transpose() + dGamma * rFr * r * r.transpose();
}

Vector3d RegularizedKelvinlet::bodyForceDensity(const Vector3d& X) const {
  const Vector3d r = X - centre_;
  const double eps2 = eps_ * eps_;
  const double re2 = r.squaredNorm() + eps2;
  const double re = std::sqrt(re2);
  const double re7 = re2 * re2 * re2 * re;
  // rho_eps = 15 eps^4 / (8 pi r_e^7)
  const double rho = 15.0 * eps2 * eps2 / (8.0 * std::numbers::pi * re7);
  if (kind_ == Kind::kGrab) return rho * force_;
  // grad rho_eps = -7 rho / r_e^2 r, so b = F grad rho_eps
  return (-7.0 * rho / re2) * (F_ * r);
}

}  // namespace sculpt
