#pragma once
// Regularized Kelvinlets (De Goes & James 2017): closed-form displacement fields of an infinite
// linear-elastic medium under a smooth, localised load. They serve as analytic ground truth for
// the embedding deformers, so every formula here is checked against the Navier equation.
//
// With a = 1 / (4 pi mu), b = a / (4 (1 - nu)), r = X - centre and r_e = sqrt(|r|^2 + eps^2):
// - grab:   u = [(a - b) / r_e I + b / r_e^3 r r^T + a eps^2 / (2 r_e^3) I] f, which solves
//           mu Lap u + mu / (1 - 2 nu) grad div u + f rho_eps = 0,
//           rho_eps(r) = 15 eps^4 / (8 pi r_e^7) (unit integral);
// - affine: the locally affine load F is sum_j d/dr_j of the grab field with force F e_j, so it
//           solves the same equation with body force b = F grad rho_eps
//           = -105 eps^4 / (8 pi r_e^9) F r. Twist, scale and pinch are F = [q]x, s I and a
//           symmetric traceless F, evaluated with their cheaper closed forms.
// The deformation is the static map phi(X) = X + u(X - centre); never integrate u as a velocity.

#include <Eigen/Core>

namespace sculpt {

/// Material of the infinite medium. The shear modulus only scales the amplitude (u ~ 1 / mu).
struct KelvinletMaterial {
  double shearModulus = 1.0;   ///< mu, > 0 (any consistent unit, Pa in SI).
  double poissonRatio = 0.45;  ///< nu, in (-1, 0.5).
};

/// One regularized Kelvinlet centred at `centre` with brush radius `eps` (> 0).
class RegularizedKelvinlet {
 public:
  /// Point-like force `force` smeared over the brush.
  static RegularizedKelvinlet grab(const Eigen::Vector3d& centre, const Eigen::Vector3d& force,
                                   double eps, KelvinletMaterial material = {});
  /// General locally affine load with matrix F (displacement ~ 1 / r^2 far away).
  static RegularizedKelvinlet affine(const Eigen::Vector3d& centre, const Eigen::Matrix3d& F,
                                     double eps, KelvinletMaterial material = {});
  /// Rotation about axis q (F = [q]x): divergence-free, so it preserves volume to first order.
  static RegularizedKelvinlet twist(const Eigen::Vector3d& centre, const Eigen::Vector3d& q,
                                    double eps, KelvinletMaterial material = {});
  /// Uniform scaling load F = s I (s > 0 pulls the material towards the centre).
  static RegularizedKelvinlet scale(const Eigen::Vector3d& centre, double s, double eps,
                                    KelvinletMaterial material = {});
  /// Pinch: F symmetric with zero trace (within 1e-12 of |F|), else std::invalid_argument.
  static RegularizedKelvinlet pinch(const Eigen::Vector3d& centre,
                                    const Eigen::Matrix3d& symmetricTraceless, double eps,
                                    KelvinletMaterial material = {});

  /// u(X - centre).
  Eigen::Vector3d displacement(const Eigen::Vector3d& X) const;
  /// The static deformation map phi(X) = X + u(X - centre).
  Eigen::Vector3d map(const Eigen::Vector3d& X) const { return X + displacement(X); }
  /// Analytic d u / d X (row i = gradient of u_i); the deformation gradient is I + this.
  Eigen::Matrix3d displacementGradient(const Eigen::Vector3d& X) const;
  /// The load density b that u balances: mu Lap u + mu / (1 - 2 nu) grad div u + b = 0.
  Eigen::Vector3d bodyForceDensity(const Eigen::Vector3d& X) const;

  const Eigen::Vector3d& centre() const { return centre_; }
  double eps() const { return eps_; }
  const KelvinletMaterial& material() const { return material_; }
  /// a = 1 / (4 pi mu) and b = a / (4 (1 - nu)) of the closed forms.
  double a() const { return a_; }
  double b() const { return b_; }

 private:
  enum class Kind { kGrab, kAffine, kTwist, kScale, kPinch };
  RegularizedKelvinlet(Kind kind, const Eigen::Vector3d& centre, double eps,
                       KelvinletMaterial material);

  Kind kind_;
  Eigen::Vector3d centre_;
  double eps_;
  KelvinletMaterial material_;
  double a_;
  double b_;
  Eigen::Vector3d force_ = Eigen::Vector3d::Zero();  ///< grab only
  Eigen::Matrix3d F_ = Eigen::Matrix3d::Zero();      ///< affine kinds (twist: [q]x, scale: s I)
  Eigen::Vector3d q_ = Eigen::Vector3d::Zero();      ///< twist axis
  double s_ = 0.0;                                   ///< scale factor
};

}  // namespace sculpt
